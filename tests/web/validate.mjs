// Runs the Khronos glTF Validator on one file and prints its report's counts; exits 0 only
// with 0 errors and 0 warnings (infos and hints are printed, not counted against it).
// Usage: node validate.mjs file.glb
import fs from 'node:fs';
import path from 'node:path';
import validator from 'gltf-validator';

const file = process.argv[2];
const data = new Uint8Array(fs.readFileSync(file));
const report = await validator.validateBytes(data, {
  uri: path.basename(file),
  maxIssues: 0,  // all of them: a cap would stop the count at the first 50 infos
  externalResourceFunction: () => Promise.reject(new Error('no external resources')),
});
const issues = report.issues;
for (const m of issues.messages.slice(0, 50)) console.log(`${m.severity}\t${m.code}\t${m.pointer ?? ''}\t${m.message}`);
console.log(`errors ${issues.numErrors} warnings ${issues.numWarnings} infos ${issues.numInfos} hints ${issues.numHints}`);
process.exit(issues.numErrors === 0 && issues.numWarnings === 0 ? 0 : 1);

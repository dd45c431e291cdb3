"""Where a .glb's bytes go: each bufferView's byteLength summed by what uses it (a primitive's
attribute or indices, a mesh's morph targets, inverse bind matrices, animation keys) and the
JSON chunk, by material (bark, leaf, underbrush: meadows). Used for bench/RESULTS.md "Issue
41, fourth round" and "fifth round: gltf3". Usage: python3 bench/glb_sizes.py FILE.glb"""
import json, struct, sys, collections
data = open(sys.argv[1], 'rb').read()
jlen = struct.unpack_from('<I', data, 12)[0]
g = json.loads(data[20:20 + jlen])
views = g['bufferViews']; acc = g['accessors']
use = {}
for m in g['meshes']:
    for p in m['primitives']:
        kind = g['materials'][p['material']]['name'] if 'material' in p else 'bark'
        for k, a in p['attributes'].items(): use[acc[a]['bufferView']] = kind + ' ' + k
        for t in p.get('targets', []):
            for k, a in t.items(): use[acc[a]['bufferView']] = kind + ' morph ' + k
        if 'indices' in p: use[acc[p['indices']]['bufferView']] = kind + ' indices'
for s in g.get('skins', []): use[acc[s['inverseBindMatrices']]['bufferView']] = 'ibm'
for an in g.get('animations', []):
    for c in an['channels']:
        s = an['samplers'][c['sampler']]
        use[acc[s['input']]['bufferView']] = 'times'
        use[acc[s['output']]['bufferView']] = 'anim ' + c['target']['path']
tot = collections.Counter()
for i, v in enumerate(views): tot[use.get(i, '?')] += v['byteLength']
tot['JSON'] = jlen
print('file %.1f MB' % (len(data) / 1e6))
for k, v in sorted(tot.items(), key=lambda x: -x[1]): print('%-22s %8.1f MB' % (k, v / 1e6))
print('joints', sum(len(s['joints']) for s in g.get('skins', [])), 'meshes', len(g['meshes']), 'nodes', len(g['nodes']))

// boreas viewer: loads a .glb (from ?file= or the file chooser), frames it, and plays its
// first animation in a loop at the frame rate it was written with. Space pauses.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const info = document.getElementById('info');
const renderer = new THREE.WebGLRenderer({ antialias: true });
renderer.setPixelRatio(window.devicePixelRatio);
renderer.setSize(window.innerWidth, window.innerHeight);
document.body.appendChild(renderer.domElement);

const scene = new THREE.Scene();
scene.background = new THREE.Color(0x9fb8cf);
scene.add(new THREE.HemisphereLight(0xdfefff, 0x4a3c28, 1.2));
const sun = new THREE.DirectionalLight(0xfff4e0, 2.0);
sun.position.set(30, 60, 20);
scene.add(sun);
const ground = new THREE.Mesh(new THREE.CircleGeometry(500, 64),
                              new THREE.MeshLambertMaterial({ color: 0x56683a }));
ground.rotation.x = -Math.PI / 2;
scene.add(ground);

const camera = new THREE.PerspectiveCamera(45, window.innerWidth / window.innerHeight, 0.1, 5000);
camera.position.set(30, 15, 30);
const controls = new OrbitControls(camera, renderer.domElement);
const clock = new THREE.Clock();
let mixer = null, action = null, loaded = null, paused = false;

function show(gltf, name) {
  if (loaded) scene.remove(loaded);
  loaded = gltf.scene;
  scene.add(loaded);
  // Skinned meshes' bounds come from their bind pose: frame the joints' box instead.
  const box = new THREE.Box3().setFromObject(loaded, true);
  const center = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3());
  const reach = Math.max(size.x, size.y, size.z);
  controls.target.copy(center);
  camera.position.copy(center).add(new THREE.Vector3(0.8, 0.5, 1.0).multiplyScalar(reach));
  controls.update();
  mixer = new THREE.AnimationMixer(loaded);
  const clip = gltf.animations[0];
  action = clip ? mixer.clipAction(clip).play() : null;
  info.textContent = `${name}: ${clip ? clip.duration.toFixed(2) + ' s, ' + clip.tracks.length + ' tracks' : 'no animation'} (space pauses)`;
}

// What tests/web/viewer_plays.py reads from its probe page: the viewer as it runs.
window.boreasViewer = { renderer, scene, camera, get mixer() { return mixer; },
                       get action() { return action; }, get model() { return loaded; } };

const loader = new GLTFLoader();
const file = new URLSearchParams(location.search).get('file');
if (file) loader.load(file, (g) => show(g, file), undefined, (e) => { info.textContent = `cannot load ${file}: ${e}`; });
document.getElementById('drop').addEventListener('change', async (event) => {
  const f = event.target.files[0];
  if (f) loader.parse(await f.arrayBuffer(), '', (g) => show(g, f.name), (e) => { info.textContent = String(e); });
});
window.addEventListener('keydown', (e) => { if (e.code === 'Space') paused = !paused; });
window.addEventListener('resize', () => {
  camera.aspect = window.innerWidth / window.innerHeight;
  camera.updateProjectionMatrix();
  renderer.setSize(window.innerWidth, window.innerHeight);
});
renderer.setAnimationLoop(() => {
  const dt = clock.getDelta();
  if (mixer && !paused) mixer.update(dt);
  controls.update();
  renderer.render(scene, camera);
});

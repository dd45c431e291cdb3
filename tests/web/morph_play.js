// Loads ?file=, plays its first animation to ?t= seconds, draws one frame (so WebGL builds
// the morph programs), and writes {mesh name: [x, y, z, ...]}: each morphed mesh's
// vertices as three.js computes them (Mesh.getVertexPosition: base plus weighted targets),
// then placed by the node. The title turns "played" (or "error ...").
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const q = new URLSearchParams(location.search);
const renderer = new THREE.WebGLRenderer({ antialias: false });
renderer.setSize(256, 256);
document.body.appendChild(renderer.domElement);
const camera = new THREE.PerspectiveCamera(50, 1, 0.1, 1000);
camera.position.set(0, 5, 20);

new GLTFLoader().load(q.get('file'), (gltf) => {
  const scene = new THREE.Scene();
  scene.add(gltf.scene);
  const mixer = new THREE.AnimationMixer(gltf.scene);
  const action = mixer.clipAction(gltf.animations[0]);
  action.setLoop(THREE.LoopOnce);
  action.clampWhenFinished = true;
  action.play();
  mixer.setTime(Number(q.get('t')));
  scene.updateMatrixWorld(true);
  renderer.render(scene, camera);
  const glError = renderer.getContext().getError();
  const out = {};
  const v = new THREE.Vector3();
  gltf.scene.traverse((o) => {
    if (!o.isMesh || !o.geometry.morphAttributes.position) return;
    const n = o.geometry.attributes.position.count;
    const xyz = new Array(3 * n);
    for (let i = 0; i < n; ++i) {
      o.getVertexPosition(i, v);
      v.applyMatrix4(o.matrixWorld);
      xyz[3 * i] = v.x; xyz[3 * i + 1] = v.y; xyz[3 * i + 2] = v.z;
    }
    out[o.name] = { targets: o.geometry.morphAttributes.position.length, xyz };
  });
  document.getElementById('out').textContent = JSON.stringify({ glError, meshes: out });
  document.title = 'played';
}, undefined, (e) => { document.title = 'error ' + e; });

// Loads ?file=, poses its first animation at ?t= seconds and draws the tree mask.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const q = new URLSearchParams(location.search);
const [x0, y0, x1, y1] = q.get('box').split(',').map(Number);
const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
// The canvas's own size: a headless window's inner height is not the size asked for.
renderer.setSize(Number(q.get('w')), Number(q.get('h')));
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x000000);
const camera = new THREE.OrthographicCamera(x0, x1, y1, y0, 0.1, 10000);
camera.position.set(0, 0, 5000);
const white = new THREE.MeshBasicMaterial({ color: 0xffffff, side: THREE.DoubleSide });

new GLTFLoader().load(q.get('file'), (gltf) => {
  gltf.scene.traverse((o) => {
    if (o.isMesh) {
      o.material = white;
      o.frustumCulled = false;  // a skinned mesh's bounds are its bind pose's
    }
  });
  scene.add(gltf.scene);
  const mixer = new THREE.AnimationMixer(gltf.scene);
  // Once, held at its end: a repeating clip wraps its last key (t = duration) to the first.
  const action = mixer.clipAction(gltf.animations[0]);
  action.setLoop(THREE.LoopOnce);
  action.clampWhenFinished = true;
  action.play();
  mixer.setTime(Number(q.get('t')));
  renderer.render(scene, camera);
  document.title = 'rendered';
}, undefined, (e) => { document.title = 'error ' + e; });

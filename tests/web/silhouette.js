// Loads ?file=, poses its first animation at each of ?times= seconds and draws the tree
// mask of each, side by side (?w= x ?h= pixels apiece), through boreas's camera: from
// ?eye= toward ?target=, Y up, ?fov= degrees vertical, aspect w / h. What lies below the
// ground plane y = ?ground= is cut away, as boreas's ground hides it from an eye above it.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const q = new URLSearchParams(location.search);
const vec = (name) => new THREE.Vector3(...q.get(name).split(',').map(Number));
const times = q.get('times').split(',').map(Number);
const [w, h] = [Number(q.get('w')), Number(q.get('h'))];
const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
// The canvas's own size: a headless window's inner height is not the size asked for.
renderer.setSize(w * times.length, h);
renderer.setScissorTest(true);
renderer.clippingPlanes = [new THREE.Plane(new THREE.Vector3(0, 1, 0), -Number(q.get('ground')))];
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0x000000);
// boreas's camera (render/gl/camera.h): glm::perspective, near 0.1 m, far 3000 m.
const camera = new THREE.PerspectiveCamera(Number(q.get('fov')), w / h, 0.1, 3000);
camera.position.copy(vec('eye'));
camera.up.set(0, 1, 0);
camera.lookAt(vec('target'));
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
  times.forEach((t, i) => {
    mixer.setTime(t);
    renderer.setViewport(i * w, 0, w, h);
    renderer.setScissor(i * w, 0, w, h);
    renderer.render(scene, camera);
  });
  document.title = 'rendered';
}, undefined, (e) => { document.title = 'error ' + e; });

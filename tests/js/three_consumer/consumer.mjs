// What three.js makes of a glTF file. window.inspectGlb(url) loads it with GLTFLoader (Draco and
// meshopt decoders from the three package), draws it once with WebGL (three uploads the buffers
// and checks its shaders only then) and resolves to
//   {triangles, meshes, instances, vertices, bounds: {min, max}}   (world space)
// or {error} when the loader rejects the file.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { DRACOLoader } from 'three/addons/loaders/DRACOLoader.js';
import { MeshoptDecoder } from 'three/addons/libs/meshopt_decoder.module.js';

const draco = new DRACOLoader().setDecoderPath('/js/node_modules/three/examples/jsm/libs/draco/');
const loader = new GLTFLoader().setDRACOLoader(draco).setMeshoptDecoder(MeshoptDecoder);

const renderer = new THREE.WebGLRenderer();
renderer.setSize(64, 64);
document.body.appendChild(renderer.domElement);
const gl = renderer.getContext();
const debugInfo = gl.getExtension('WEBGL_debug_renderer_info');
window.webgl = gl.getParameter(debugInfo ? debugInfo.UNMASKED_RENDERER_WEBGL : gl.RENDERER);

// Triangles and the exact world-space box. Box3.setFromObject(scene, true) would do for plain
// meshes, but for an InstancedMesh it falls back to the conservative box of the instances.
function measure(scene) {
  scene.updateMatrixWorld(true);
  const box = new THREE.Box3();
  const p = new THREE.Vector3();
  const world = new THREE.Matrix4();
  const instance = new THREE.Matrix4();
  let triangles = 0, meshes = 0, instances = 0, vertices = 0;
  scene.traverse((o) => {
    if (!o.isMesh) return;  // lines and points are no triangles
    const g = o.geometry;
    const position = g.getAttribute('position');
    const copies = o.isInstancedMesh ? o.count : 1;
    meshes += 1;
    instances += copies;
    triangles += copies * (g.index ? g.index.count : position.count) / 3;
    vertices += copies * position.count;
    for (let c = 0; c < copies; ++c) {
      world.copy(o.matrixWorld);
      if (o.isInstancedMesh) {
        o.getMatrixAt(c, instance);
        world.multiply(instance);
      }
      // getX/getY/getZ undo the normalization of quantized attributes.
      for (let i = 0; i < position.count; ++i)
        box.expandByPoint(p.fromBufferAttribute(position, i).applyMatrix4(world));
    }
  });
  return { triangles, meshes, instances, vertices,
           bounds: { min: box.min.toArray(), max: box.max.toArray() } };
}

function draw(scene, bounds) {
  const box = new THREE.Box3(new THREE.Vector3(...bounds.min), new THREE.Vector3(...bounds.max));
  const centre = box.getCenter(new THREE.Vector3());
  const radius = Math.max(box.getSize(new THREE.Vector3()).length() / 2, 1e-6);
  const camera = new THREE.PerspectiveCamera(45, 1, radius / 100, radius * 10);
  camera.position.copy(centre).add(new THREE.Vector3(0, 0, 3 * radius));
  camera.lookAt(centre);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 3));
  renderer.render(scene, camera);
}

function dispose(scene) {
  scene.traverse((o) => {
    o.geometry?.dispose();
    for (const m of [o.material ?? []].flat()) m.dispose();
  });
}

window.inspectGlb = async (url) => {
  let gltf;
  try {
    gltf = await loader.loadAsync(url);
  } catch (e) {
    return { error: String(e?.message ?? e) };
  }
  const result = measure(gltf.scene);
  if (result.meshes > 0) draw(gltf.scene, result.bounds);
  dispose(gltf.scene);
  return result;
};

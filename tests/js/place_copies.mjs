// Writes OUT.glb: the first mesh of IN.glb placed N times by N nodes, each translated by
// (2 * diagonal * k, 0, 0), with @gltf-transform/core (so that `gltf-transform instance` has
// repeated meshes to turn into EXT_mesh_gpu_instancing).
//   node place_copies.mjs IN.glb OUT.glb N
import { NodeIO } from '@gltf-transform/core';

const [input, output, count] = process.argv.slice(2);
if (!output || !(Number(count) > 0)) {
  console.error('usage: node place_copies.mjs IN.glb OUT.glb N');
  process.exit(2);
}
const io = new NodeIO();
const document = await io.read(input);
const root = document.getRoot();
const mesh = root.listMeshes()[0];
const position = mesh.listPrimitives()[0].getAttribute('POSITION');
const lo = position.getMin([]), hi = position.getMax([]);
const diagonal = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
const scene = root.listScenes()[0];
for (const node of scene.listChildren()) scene.removeChild(node);
for (let k = 0; k < Number(count); ++k)
  scene.addChild(document.createNode(`copy${k}`).setMesh(mesh).setTranslation([2 * diagonal * k, 0, 0]));
await io.write(output, document);

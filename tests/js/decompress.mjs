// Writes OUT.glb: IN.glb with its Draco and meshopt compression decoded (the official decoders,
// draco3dgltf and meshoptimizer, through @gltf-transform), so that the Khronos validator, which
// does not look inside compressed buffers, can check the geometry itself. Several pairs in one
// run: node's start and the decoders' set-up are most of the time of one file.
//   node decompress.mjs IN.glb OUT.glb [IN2.glb OUT2.glb ...]
import { NodeIO } from '@gltf-transform/core';
import { KHRDracoMeshCompression, EXTMeshoptCompression, KHRMeshQuantization } from '@gltf-transform/extensions';
import draco3d from 'draco3dgltf';
import { MeshoptDecoder } from 'meshoptimizer';

const files = process.argv.slice(2);
if (files.length === 0 || files.length % 2 !== 0) {
  console.error('usage: node decompress.mjs IN.glb OUT.glb [IN2.glb OUT2.glb ...]');
  process.exit(2);
}
await MeshoptDecoder.ready;
const io = new NodeIO()
  .registerExtensions([KHRDracoMeshCompression, EXTMeshoptCompression, KHRMeshQuantization])
  .registerDependencies({ 'draco3d.decoder': await draco3d.createDecoderModule(), 'meshopt.decoder': MeshoptDecoder });
for (let i = 0; i < files.length; i += 2) {
  const document = await io.read(files[i]);
  for (const extension of document.getRoot().listExtensionsUsed()) {
    if (extension.extensionName !== 'KHR_mesh_quantization') extension.dispose();
  }
  await io.write(files[i + 1], document);
}

// Writes OUT.glb: IN.glb with its Draco and meshopt compression decoded (the official decoders,
// draco3dgltf and meshoptimizer, through @gltf-transform), so that the Khronos validator, which
// does not look inside compressed buffers, can check the geometry itself.
//   node decompress.mjs IN.glb OUT.glb
import { NodeIO } from '@gltf-transform/core';
import { KHRDracoMeshCompression, EXTMeshoptCompression, KHRMeshQuantization } from '@gltf-transform/extensions';
import draco3d from 'draco3dgltf';
import { MeshoptDecoder } from 'meshoptimizer';

const [input, output] = process.argv.slice(2);
if (!output) {
  console.error('usage: node decompress.mjs IN.glb OUT.glb');
  process.exit(2);
}
await MeshoptDecoder.ready;
const io = new NodeIO()
  .registerExtensions([KHRDracoMeshCompression, EXTMeshoptCompression, KHRMeshQuantization])
  .registerDependencies({ 'draco3d.decoder': await draco3d.createDecoderModule(), 'meshopt.decoder': MeshoptDecoder });
const document = await io.read(input);
for (const extension of document.getRoot().listExtensionsUsed()) {
  if (extension.extensionName !== 'KHR_mesh_quantization') extension.dispose();
}
await io.write(output, document);

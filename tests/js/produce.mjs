// Makes glTF files with third-party producers, several in one node run: each command-line tool's
// start (its bundle, the encoders' set-up) is most of the time of one file. Each operation makes
// the library call its command-line tool makes, with that tool's defaults:
//   obj2gltf IN.obj OUT.glb    obj2gltf -i IN.obj -o OUT.glb
//   draco IN.glb OUT.glb       gltf-pipeline -i IN.glb -o OUT.glb -d
//   meshopt IN.glb OUT.glb     gltf-transform meshopt IN.glb OUT.glb (level high)
//   quantize IN.glb OUT.glb    gltf-transform quantize IN.glb OUT.glb
//   instance IN.glb OUT.glb    gltf-transform instance IN.glb OUT.glb
// The operations run in the order given (a later one may read an earlier one's output).
//   node produce.mjs OP IN OUT [OP IN OUT ...]
import fs from 'fs';
import path from 'path';
import { createRequire } from 'module';
import { NodeIO } from '@gltf-transform/core';
import { ALL_EXTENSIONS } from '@gltf-transform/extensions';
import { instance, meshopt, quantize, unpartition } from '@gltf-transform/functions';
import draco3d from 'draco3dgltf';
import { MeshoptDecoder, MeshoptEncoder } from 'meshoptimizer';

const require = createRequire(import.meta.url);
const obj2gltf = require('obj2gltf');
const { processGlb } = require('gltf-pipeline');

const args = process.argv.slice(2);
const ops = ['obj2gltf', 'draco', 'meshopt', 'quantize', 'instance'];
if (args.length === 0 || args.length % 3 !== 0 || args.some((a, i) => i % 3 === 0 && !ops.includes(a))) {
  console.error(`usage: node produce.mjs OP IN OUT [OP IN OUT ...], OP one of ${ops.join(', ')}`);
  process.exit(2);
}

// gltf-transform's command-line configuration: every extension, both codecs.
await Promise.all([MeshoptDecoder.ready, MeshoptEncoder.ready]);
const io = new NodeIO().registerExtensions(ALL_EXTENSIONS).registerDependencies({
  'draco3d.decoder': await draco3d.createDecoderModule(),
  'draco3d.encoder': await draco3d.createEncoderModule(),
  'meshopt.decoder': MeshoptDecoder,
  'meshopt.encoder': MeshoptEncoder,
});

// As gltf-transform's Session: the transform, then one buffer for a .glb.
async function transformed(input, output, transform) {
  const document = await io.read(input);
  await document.transform(transform, unpartition());
  await io.write(output, document);
}

for (let i = 0; i < args.length; i += 3) {
  const [op, input, output] = args.slice(i, i + 3);
  if (op === 'obj2gltf') {
    fs.writeFileSync(output, await obj2gltf(input, { binary: true }));
  } else if (op === 'draco') {
    const name = path.basename(output, path.extname(output));  // the buffer's name, as the CLI
    const { glb } = await processGlb(fs.readFileSync(input), { dracoOptions: {}, name });
    fs.writeFileSync(output, glb);
  } else if (op === 'meshopt') {
    await transformed(input, output, meshopt({ encoder: MeshoptEncoder, level: 'high' }));
  } else if (op === 'quantize') {
    await transformed(input, output, quantize());
  } else {
    await transformed(input, output, instance());
  }
}

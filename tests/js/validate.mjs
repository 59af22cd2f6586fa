// Runs the Khronos glTF-Validator on each file given and prints one JSON line per file:
// {"file", "errors", "warnings", "infos", "hints", "messages": [first few as "CODE at POINTER: text"]}.
// Exit 0 when no file has an error or a warning, 1 otherwise, 2 on a usage or I/O error.
import fs from 'node:fs';
import path from 'node:path';
import validator from 'gltf-validator';

const files = process.argv.slice(2);
if (files.length === 0) {
  console.error('usage: node validate.mjs FILE.glb|FILE.gltf...');
  process.exit(2);
}
let failed = false;
for (const file of files) {
  let bytes;
  try {
    bytes = new Uint8Array(fs.readFileSync(file));
  } catch (e) {
    console.error(`${file}: cannot read: ${e.message}`);
    process.exit(2);
  }
  const folder = path.dirname(file);
  const report = await validator.validateBytes(bytes, {
    uri: path.basename(file),
    maxIssues: 100,
    // External resources only from beside the file, as proxyvis itself reads them.
    externalResourceFunction: (uri) =>
      new Promise((resolve, reject) => {
        const target = path.resolve(folder, decodeURIComponent(uri));
        if (!target.startsWith(path.resolve(folder) + path.sep)) return reject(new Error('outside'));
        fs.readFile(target, (err, data) => (err ? reject(err) : resolve(new Uint8Array(data))));
      }),
  });
  const issues = report.issues;
  const messages = issues.messages
    .filter((m) => m.severity <= 1)
    .slice(0, 5)
    .map((m) => `${m.code} at ${m.pointer ?? '-'}: ${m.message}`);
  console.log(JSON.stringify({
    file, errors: issues.numErrors, warnings: issues.numWarnings, infos: issues.numInfos,
    hints: issues.numHints, messages,
    info: issues.messages.filter((m) => m.severity === 2).map((m) => m.code),
  }));
  if (issues.numErrors > 0 || issues.numWarnings > 0) failed = true;
}
process.exit(failed ? 1 : 0);

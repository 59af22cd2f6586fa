// Loads glTF files with three.js in headless Chromium (one start for all of them: it costs
// seconds) and prints one JSON line per file:
//   {"file", "triangles", "meshes", "instances", "vertices", "bounds": {"min", "max"},
//    "error" (when the loader rejected it), "console": ["type: text", ...]}
// "console" holds what the page logged while that file loaded (also uncaught errors and failed
// requests). A first line {"page": true, "webgl": RENDERER, "console": [...]} holds the WebGL
// renderer and what the page logged at start.
//   node run.mjs CHROMIUM FILE.glb...
// Exit 0 when every file was inspected (whatever it held), 2 when Chromium or the page failed.
// Everything is served by a server of this process on 127.0.0.1: no network.
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const [executablePath, ...files] = process.argv.slice(2);
if (!executablePath || files.length === 0) {
  console.error('usage: node run.mjs CHROMIUM FILE.glb...');
  process.exit(2);
}
const jsDir = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '..');
const types = { '.html': 'text/html', '.js': 'text/javascript', '.mjs': 'text/javascript',
                '.wasm': 'application/wasm', '.glb': 'model/gltf-binary' };

// /js/PATH: tests/js/PATH; /glb/I/NAME: the I-th file given (its own name keeps messages readable).
function resolve(url) {
  const p = decodeURIComponent(new URL(url, 'http://x').pathname);
  const glb = p.match(/^\/glb\/(\d+)\/[^/]+$/);
  if (glb) return files[Number(glb[1])];
  if (!p.startsWith('/js/')) return undefined;
  const target = path.resolve(jsDir, '.' + p.slice(3));
  return target.startsWith(jsDir + path.sep) ? target : undefined;
}

const server = http.createServer((req, res) => {
  const file = resolve(req.url);
  fs.readFile(file ?? '', (err, data) => {
    if (err) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'Content-Type': types[path.extname(file)] ?? 'application/octet-stream' });
    res.end(data);
  });
});
await new Promise((ok) => server.listen(0, '127.0.0.1', ok));
const origin = `http://127.0.0.1:${server.address().port}`;

let browser;
let status = 0;
try {
  // SwiftShader: WebGL without a GPU.
  browser = await chromium.launch({
    executablePath,
    args: ['--use-gl=angle', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  const page = await browser.newPage();
  let log = [];
  page.on('console', (m) => log.push(`${m.type()}: ${m.text()}`));
  page.on('pageerror', (e) => log.push(`pageerror: ${e.message}`));
  page.on('requestfailed', (r) => log.push(`requestfailed: ${r.url()} ${r.failure()?.errorText}`));
  await page.goto(`${origin}/js/three_consumer/index.html`);
  await page.waitForFunction(() => window.inspectGlb !== undefined, null, { timeout: 30000 })
    .catch((e) => {
      throw new Error(`the page did not start: ${log.join(' | ') || e.message}`);
    });
  const webgl = await page.evaluate(() => window.webgl);
  console.log(JSON.stringify({ page: true, webgl, console: log }));
  for (const [i, file] of files.entries()) {
    log = [];
    const url = `/glb/${i}/${encodeURIComponent(path.basename(file))}`;
    const result = await page.evaluate((u) => window.inspectGlb(u), url);
    console.log(JSON.stringify({ file, ...result, console: log }));
  }
} catch (e) {
  console.error(`three_consumer: ${e.message}`);
  status = 2;
} finally {
  await browser?.close();
  server.close();
}
process.exit(status);

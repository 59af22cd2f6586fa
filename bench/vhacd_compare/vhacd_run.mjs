#!/usr/bin/env node
// Runs V-HACD (npm package vhacd-js 0.0.1, a WebAssembly build) on one mesh and
// writes its convex hulls as one OBJ. Used by bench_vhacd.py as the unproved baseline to
// compare against proxyvis' proved outside proxies.
import { readFileSync, writeFileSync, renameSync } from "node:fs";
import { extname } from "node:path";
import { parseArgs } from "node:util";
// We use the package's embind module (lib/vhacd-wasm.js) rather than its wrapper
// ConvexMeshDecomposition (lib/vhacd.js): the wrapper assigns plain numbers to the
// embind enum fields (fill mode, message type), which embind turns into 0, so
// --fill-mode and --messages would silently be ignored. We make the same calls as
// the wrapper, with the real enum values. (The package also has no "main" entry,
// so the bare specifier "vhacd-js" does not resolve under Node.)
import instantiateVhacd from "vhacd-js/lib/vhacd-wasm.js";

// Every parameter vhacd-js exposes, keyed by its name on the embind Parameters
// object, with the CLI flag (V-HACD's own parameter name in kebab case) and the
// default from VHACD.h (the same values a fresh Parameters object holds).
const PARAMS = {
  maxHulls:              { flag: "max-hulls",                kind: "int",   min: 1, def: 64 },      // m_maxConvexHulls
  maxVerticesPerHull:    { flag: "max-vertices-per-hull",    kind: "int",   min: 4, def: 64 },      // m_maxNumVerticesPerCH
  voxelResolution:       { flag: "resolution",               kind: "int",   min: 1, def: 400000 },  // m_resolution
  minVolumePercentError: { flag: "min-volume-percent-error", kind: "float", min: 0, def: 1 },       // m_minimumVolumePercentErrorAllowed
  maxRecursionDepth:     { flag: "max-recursion-depth",      kind: "int",   min: 0, def: 10 },      // m_maxRecursionDepth
  minEdgeLength:         { flag: "min-edge-length",          kind: "int",   min: 0, def: 2 },       // m_minEdgeLength
  shrinkWrap:            { flag: "shrink-wrap",              kind: "bool",  def: true },            // m_shrinkWrap
  findBestPlane:         { flag: "find-best-plane",          kind: "bool",  def: false },           // m_findBestPlane
  fillMode:              { flag: "fill-mode",                kind: ["flood", "surface", "raycast"], def: "flood" }, // m_fillMode
  messages:              { flag: "messages",                 kind: ["none", "progress", "log", "all"], def: "none" }, // V-HACD logging, sent to stderr
};

const USAGE = `usage: node vhacd_run.mjs --in MESH --out HULLS.obj [options]

Runs V-HACD (vhacd-js 0.0.1) on MESH (ASCII .obj, .off or .ply) and writes every
convex hull as its own "o hull_<i>" object to HULLS.obj. Prints one JSON line
{input, input_vertices, input_faces, hulls, faces, vertices, seconds, parameters}.

options (V-HACD parameter names; default in brackets):
${Object.values(PARAMS).map((p) =>
  `  --${(p.flag + " " + (Array.isArray(p.kind) ? p.kind.join("|") : p.kind === "bool" ? "true|false" : "N")).padEnd(38)} [${p.def}]`).join("\n")}
  --help                                   print this and exit

exit status: 0 ok, 2 bad arguments or unreadable input, 1 V-HACD or output failure.`;

class Fail extends Error {
  constructor(message, code) { super(message); this.code = code; }
}

// ---------- command line ----------

function parseCommandLine(argv) {
  const options = { in: { type: "string" }, out: { type: "string" }, help: { type: "boolean" } };
  for (const p of Object.values(PARAMS)) options[p.flag] = { type: "string" };
  let values;
  try {
    ({ values } = parseArgs({ args: argv, options, strict: true, allowPositionals: false }));
  } catch (e) {
    throw new Fail(`${e.message.replace(/\s*\n\s*/g, " ")} (see --help)`, 2); // keep it one line
  }
  if (values.help) return { help: true };
  if (!values.in || !values.out) throw new Fail("--in MESH and --out HULLS.obj are required (see --help)", 2);

  const params = {};
  for (const [key, p] of Object.entries(PARAMS)) {
    const text = values[p.flag];
    params[key] = text === undefined ? p.def : parseValue(p, text);
  }
  return { input: values.in, output: values.out, params };
}

function parseValue(p, text) {
  const bad = (want) => new Fail(`--${p.flag} ${JSON.stringify(text)}: expected ${want}`, 2);
  if (Array.isArray(p.kind)) {
    if (!p.kind.includes(text)) throw bad(p.kind.join(" or "));
    return text;
  }
  if (p.kind === "bool") {
    if (text === "true" || text === "1") return true;
    if (text === "false" || text === "0") return false;
    throw bad("true or false");
  }
  const x = Number(text);
  // Embind stores these into uint32/double fields and would silently wrap or truncate bad values.
  if (text.trim() === "" || !Number.isFinite(x) || x < p.min || (p.kind === "int" && (!Number.isInteger(x) || x > 0xffffffff)))
    throw bad(`${p.kind === "int" ? "an integer" : "a number"} >= ${p.min}`);
  return x;
}

// ---------- mesh readers: each returns { positions: number[], triangles: number[] } ----------

// Fan-triangulates polygon `poly` (0-based indices) into `out`, checking the indices.
function addPolygon(out, poly, nVertices, where) {
  if (poly.length < 3) throw new Error(`${where}: face with fewer than 3 vertices`);
  for (const i of poly)
    if (!Number.isInteger(i) || i < 0 || i >= nVertices) throw new Error(`${where}: vertex index out of range`);
  for (let k = 1; k + 1 < poly.length; k++) out.push(poly[0], poly[k], poly[k + 1]);
}

function parseCoords(tokens, where) {
  const xyz = tokens.slice(0, 3).map(Number);
  if (xyz.length < 3 || !xyz.every(Number.isFinite)) throw new Error(`${where}: bad vertex coordinates`);
  return xyz;
}

function readObj(text) {
  const positions = [], triangles = [];
  const lines = text.split(/\r?\n/);
  for (let n = 0; n < lines.length; n++) {
    const t = lines[n].trim().split(/\s+/);
    const where = `line ${n + 1}`;
    if (t[0] === "v") {
      positions.push(...parseCoords(t.slice(1), where));
    } else if (t[0] === "f") {
      const nv = positions.length / 3;
      // "a", "a/b", "a//c", "a/b/c": only the position index matters; negative counts back from the last vertex so far.
      const poly = t.slice(1).map((s) => {
        const i = parseInt(s.split("/")[0], 10);
        return i < 0 ? nv + i : i - 1;
      });
      addPolygon(triangles, poly, nv, where);
    }
  }
  return { positions, triangles };
}

function readOff(text) {
  // Drop comments and blank lines; keep lines so extra per-vertex/per-face data (colours) can be ignored.
  const lines = text.split(/\r?\n/).map((l, n) => ({ t: l.replace(/#.*/, "").trim().split(/\s+/), n: n + 1 }))
    .filter((l) => l.t[0] !== "");
  if (!lines.length || !/^[A-Z]*OFF$/.test(lines[0].t[0])) throw new Error("missing OFF header");
  // The counts may follow "OFF" on the same line or stand on the next one.
  const sameLine = lines[0].t.length > 1;
  const [nv, nf] = (sameLine ? lines[0].t.slice(1) : lines[1]?.t ?? []).map(Number);
  let k = sameLine ? 1 : 2;
  if (!Number.isInteger(nv) || !Number.isInteger(nf) || nv < 0 || nf < 0) throw new Error("bad vertex/face counts");
  if (lines.length < k + nv + nf) throw new Error(`file ends early: expected ${nv} vertices and ${nf} faces`);
  const positions = [], triangles = [];
  for (let i = 0; i < nv; i++, k++) positions.push(...parseCoords(lines[k].t, `line ${lines[k].n}`));
  for (let i = 0; i < nf; i++, k++) {
    const t = lines[k].t.map(Number), m = t[0];
    if (t.length < 1 + m) throw new Error(`line ${lines[k].n}: face has fewer indices than its count`);
    addPolygon(triangles, t.slice(1, 1 + m), nv, `line ${lines[k].n}`);
  }
  return { positions, triangles };
}

function readPly(buffer) {
  // The header is ASCII even in binary files; read it to tell which kind this is.
  const head = buffer.subarray(0, Math.min(buffer.length, 65536)).toString("latin1");
  const end = /end_header\r?\n/.exec(head);
  if (!head.startsWith("ply") || !end) throw new Error("missing PLY header");
  const header = head.slice(0, end.index).split(/\r?\n/).map((l) => l.trim().split(/\s+/));
  const format = header.find((t) => t[0] === "format")?.[1] ?? "missing";
  if (format !== "ascii") throw new Error(`PLY format is ${format}, only ASCII PLY is read: convert it to OBJ`);

  // Elements in file order, each with its properties (lists consume "count item...").
  const elements = [];
  for (const t of header) {
    if (t[0] === "element") elements.push({ name: t[1], count: Number(t[2]), props: [] });
    else if (t[0] === "property") elements.at(-1)?.props.push({ name: t.at(-1), list: t[1] === "list" });
  }
  // In ASCII PLY every element instance is one line.
  const lines = buffer.toString("latin1", end.index + end[0].length).split(/\r?\n/)
    .map((l) => l.trim()).filter((l) => l !== "");
  const positions = [], triangles = [];
  let k = 0, nv = 0;
  for (const el of elements) {
    if (lines.length < k + el.count) throw new Error(`file ends early in element ${el.name}`);
    for (let i = 0; i < el.count; i++, k++) {
      const tok = lines[k].split(/\s+/).map(Number);
      const rec = {};
      let j = 0;
      for (const p of el.props) {
        if (p.list) { const m = tok[j++]; rec[p.name] = tok.slice(j, j + m); j += m; }
        else rec[p.name] = tok[j++];
      }
      if (el.name === "vertex") positions.push(...parseCoords([rec.x, rec.y, rec.z], `vertex ${i}`));
      else if (el.name === "face") addPolygon(triangles, rec.vertex_indices ?? rec.vertex_index ?? [], nv, `face ${i}`);
    }
    if (el.name === "vertex") nv = el.count;
  }
  return { positions, triangles };
}

function readMesh(path) {
  const ext = extname(path).toLowerCase();
  if (![".obj", ".off", ".ply"].includes(ext))
    throw new Fail(`${path}: cannot read mesh: unknown extension "${ext}" (expected .obj, .off or .ply)`, 2);
  try {
    const buffer = readFileSync(path);
    const mesh = ext === ".ply" ? readPly(buffer) : ext === ".off" ? readOff(buffer.toString("utf8")) : readObj(buffer.toString("utf8"));
    if (mesh.triangles.length === 0) throw new Error("no faces");
    return mesh;
  } catch (e) {
    throw new Fail(`${path}: cannot read mesh: ${e.message}`, 2);
  }
}

// ---------- V-HACD ----------

const enumName = (e, value) => Object.keys(e).find((k) => e[k] === value)?.toLowerCase();
const enumValue = (e, name) => e[name[0].toUpperCase() + name.slice(1)];

// Runs V-HACD once. Returns the hulls ({positions, indices} copied out of the wasm heap),
// the wall time of the compute call, and the parameters as read back from the wasm object.
function decompose(wasm, mesh, params) {
  const p = new wasm.Parameters();
  let pPoints = 0, pTriangles = 0, decomposer, list;
  try {
    for (const key of Object.keys(PARAMS))
      if (key === "fillMode") p.fillMode = enumValue(wasm.FillMode, params.fillMode);
      else if (key !== "messages") p[key] = params[key];
    // Read back what the wasm side holds, so the report cannot disagree with what ran.
    const used = {};
    for (const key of Object.keys(PARAMS))
      used[key] = key === "fillMode" ? enumName(wasm.FillMode, p.fillMode) : key === "messages" ? params.messages : p[key];

    // Allocate both buffers before filling either: a malloc may grow (and replace) the heap views.
    pPoints = wasm._malloc(8 * mesh.positions.length);
    pTriangles = wasm._malloc(4 * mesh.indices.length);
    wasm.HEAPF64.set(mesh.positions, pPoints / 8);
    wasm.HEAPU32.set(mesh.indices, pTriangles / 4);
    decomposer = new wasm.MeshDecomposer(p, enumValue(wasm.MessageType, params.messages));

    const t0 = process.hrtime.bigint();
    list = decomposer.compute(pPoints, mesh.positions.length / 3, pTriangles, mesh.indices.length / 3);
    const seconds = Number(process.hrtime.bigint() - t0) / 1e9;

    // The hulls point into memory owned by the decomposer: copy them out before disposing of it.
    const hulls = [];
    for (let i = 0; i < list.size(); i++) {
      const h = list.get(i), pts = h.getPoints() / 8, tris = h.getTriangles() / 4;
      hulls.push({
        positions: wasm.HEAPF64.slice(pts, pts + 3 * h.numPoints),
        indices: wasm.HEAPU32.slice(tris, tris + 3 * h.numTriangles),
      });
      h.delete();
    }
    return { hulls, seconds, used };
  } finally {
    list?.delete();
    decomposer?.dispose(); // the package's way to free a MeshDecomposer
    if (pPoints) wasm._free(pPoints);
    if (pTriangles) wasm._free(pTriangles);
    p.delete();
  }
}

// ---------- output ----------

// Six times the signed volume of a closed triangle mesh; positive when it is oriented outward.
function signedVolume6(positions, indices) {
  let v = 0;
  for (let t = 0; t < indices.length; t += 3) {
    const [a, b, c] = [indices[t], indices[t + 1], indices[t + 2]].map((i) => positions.subarray(3 * i, 3 * i + 3));
    v += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return v;
}

function writeHulls(path, hulls) {
  // Number -> string is the shortest round-trip form, so coordinates are written exactly.
  const out = [`# ${hulls.length} convex hulls from V-HACD (vhacd-js 0.0.1)`];
  let base = 1;
  hulls.forEach((h, i) => {
    out.push(`o hull_${i}`);
    for (let j = 0; j < h.positions.length; j += 3) out.push(`v ${h.positions[j]} ${h.positions[j + 1]} ${h.positions[j + 2]}`);
    for (let j = 0; j < h.indices.length; j += 3) out.push(`f ${h.indices[j] + base} ${h.indices[j + 1] + base} ${h.indices[j + 2] + base}`);
    base += h.positions.length / 3;
  });
  // Write aside then rename, so a reader never sees a half-written file.
  try {
    writeFileSync(path + ".tmp", out.join("\n") + "\n");
    renameSync(path + ".tmp", path);
  } catch (e) {
    throw new Fail(`${path}: cannot write hulls: ${e.message}`, 1);
  }
}

// ---------- main ----------

async function main() {
  const cmd = parseCommandLine(process.argv.slice(2));
  if (cmd.help) { console.log(USAGE); return; }
  const mesh = readMesh(cmd.input);

  const wasm = await instantiateVhacd(); // instantiates the WebAssembly module (not timed)
  const input = { positions: new Float64Array(mesh.positions), indices: new Uint32Array(mesh.triangles) };

  // V-HACD's messages go to console.log; keep stdout for the one JSON object.
  const log = console.log;
  console.log = console.error;
  let result;
  try {
    result = decompose(wasm, input, cmd.params);
  } catch (e) {
    throw new Fail(`${cmd.input}: V-HACD failed: ${e?.message ?? e}`, 1);
  } finally {
    console.log = log;
  }
  const { hulls, seconds, used } = result;
  if (hulls.length === 0) throw new Fail(`${cmd.input}: V-HACD failed: it returned no hulls`, 1);

  hulls.forEach((h, i) => {
    if (!(signedVolume6(h.positions, h.indices) > 0))
      console.error(`vhacd_run: warning: hull_${i} has non-positive signed volume (inverted or flat)`);
  });
  writeHulls(cmd.output, hulls);

  const sum = (f) => hulls.reduce((s, h) => s + f(h), 0);
  console.log(JSON.stringify({
    input: cmd.input,
    input_vertices: mesh.positions.length / 3,
    input_faces: mesh.triangles.length / 3,
    hulls: hulls.length,
    faces: sum((h) => h.indices.length / 3),
    vertices: sum((h) => h.positions.length / 3),
    seconds,
    parameters: used,
  }));
}

main().catch((e) => {
  console.error(`vhacd_run: ${e instanceof Fail ? e.message : e?.stack ?? e}`);
  process.exit(e instanceof Fail ? e.code : 1);
});

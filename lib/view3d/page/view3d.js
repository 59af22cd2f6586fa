// The 3D view of a page written by lib/view3d/view3d_html.cpp (docs/report_3d.md): original,
// proxy and segment layers from the page's embedded data, drawn with the embedded three.js,
// orbit controls, one checkbox per layer. Renders on demand (after a change), not in a loop.
// When done, <html data-view3d> is "ready" (or "failed") and window.pvView3d describes what is
// drawn, for the page test (tests/apps/proxy_check_view3d.py).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const root = document.documentElement;
const status = document.getElementById('view3d-status');
const viewport = document.getElementById('viewport');

function fail(message) {
  root.dataset.view3d = 'failed';
  status.textContent = message;
  status.hidden = false;
}

function decode(base64) {
  const text = atob(base64);
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  return bytes.buffer;
}

function webglAvailable() {
  const canvas = document.createElement('canvas');
  return !!(canvas.getContext('webgl2') || canvas.getContext('webgl'));
}

function meshGeometry(mesh) {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position',
                        new THREE.BufferAttribute(new Float32Array(decode(mesh.positions)), 3));
  geometry.setIndex(new THREE.BufferAttribute(new Uint32Array(decode(mesh.indices)), 1));
  geometry.computeVertexNormals();
  return geometry;
}

function build(data) {
  const renderer = new THREE.WebGLRenderer({ antialias: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  viewport.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf3f4f6);
  const radius = data.radius > 0 ? data.radius : 1;
  const camera = new THREE.PerspectiveCamera(40, 1, radius / 500, radius * 50);
  // A light from the camera's side, so that what the view faces is lit after any orbit.
  const light = new THREE.DirectionalLight(0xffffff, 2.2);
  light.position.set(0.4, 0.8, 1);
  camera.add(light);
  scene.add(camera, new THREE.HemisphereLight(0xffffff, 0x8a8f99, 0.9));

  const layers = {};
  const original = new THREE.Mesh(meshGeometry(data.original), new THREE.MeshLambertMaterial({
    color: 0xc9b48f, side: THREE.DoubleSide,
    polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1,
  }));
  original.renderOrder = 0;
  scene.add(original);
  layers.original = { object: original, triangles: data.original.triangles };

  const proxyGeometry = meshGeometry(data.proxy);
  const surface = new THREE.Mesh(proxyGeometry, new THREE.MeshLambertMaterial({
    color: 0x14948b, side: THREE.DoubleSide, transparent: true, opacity: 0.22, depthWrite: false,
  }));
  surface.renderOrder = 2;
  const proxy = new THREE.Group();
  proxy.add(surface);
  let wireframe = null;  // built on first use: large proxies start without it
  function proxyStyle(style) {
    if (style !== 'translucent' && !wireframe) {
      wireframe = new THREE.LineSegments(new THREE.WireframeGeometry(proxyGeometry),
                                         new THREE.LineBasicMaterial({
                                           color: 0x0b5e58, transparent: true, opacity: 0.45,
                                         }));
      wireframe.renderOrder = 3;
      proxy.add(wireframe);
    }
    surface.visible = style !== 'wireframe';
    if (wireframe) wireframe.visible = style !== 'translucent';
  }
  scene.add(proxy);
  layers.proxy = { object: proxy, triangles: data.proxy.triangles };

  for (const layer of data.layers) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position',
                          new THREE.BufferAttribute(new Float32Array(decode(layer.positions)), 3));
    const lines = new THREE.LineSegments(geometry,
                                         new THREE.LineBasicMaterial({
                                           color: layer.color, transparent: true, opacity: 0.45,
                                           depthWrite: false,
                                         }));
    lines.renderOrder = 1;
    scene.add(lines);
    layers[layer.id] = { object: lines, counted: layer.counted, drawn: layer.drawn };
  }

  const controls = new OrbitControls(camera, renderer.domElement);
  const home = new THREE.Vector3(0.55, 0.35, 1).normalize().multiplyScalar(radius * 2.6);
  function resetView() {
    camera.position.copy(home);
    controls.target.set(0, 0, 0);
    controls.update();
  }

  const state = { frames: 0, layers: {} };
  function render() {
    renderer.render(scene, camera);
    state.frames += 1;
    state.triangles = renderer.info.render.triangles;
    state.lines = renderer.info.render.lines;
  }
  function resize() {
    const width = Math.max(1, viewport.clientWidth), height = Math.max(1, viewport.clientHeight);
    renderer.setSize(width, height);
    camera.aspect = width / height;
    camera.updateProjectionMatrix();
    render();
  }

  for (const [id, layer] of Object.entries(layers)) {
    const box = document.getElementById('layer-' + id);
    const apply = () => {
      layer.object.visible = box.checked;
      state.layers[id] = Object.assign({ visible: box.checked }, layer, { object: undefined });
    };
    apply();
    box.addEventListener('change', () => { apply(); render(); });
  }
  const style = document.getElementById('proxy-style');
  proxyStyle(style.value);
  style.addEventListener('change', () => { proxyStyle(style.value); render(); });
  document.getElementById('reset-view').addEventListener('click', () => { resetView(); render(); });
  controls.addEventListener('change', render);
  resetView();
  new ResizeObserver(resize).observe(viewport);
  resize();
  status.hidden = true;
  window.pvView3d = state;
  root.dataset.view3d = 'ready';
}

try {
  if (!webglAvailable()) {
    fail('The 3D view needs WebGL, which this browser does not offer; the tables above hold ' +
         'the results.');
  } else {
    build(JSON.parse(document.getElementById('pv-view3d-data').textContent));
  }
} catch (error) {
  fail('The 3D view could not be built: ' + error.message);
}

#!/usr/bin/env python3
"""proxy-check --html in a browser: the page's 3D view (docs/report_3d.md) in headless Chromium
with WebGL (SwiftShader), driven over the DevTools protocol on a pipe (standard library only).

Writes an outside proxy of data/bunny.off with proxy-gen and a planted defect (that proxy scaled
down by 10 % about its centre, so that HM' segments exist), runs proxy-check --expect outside
--html on both (and takes proxy-gen --report's page of the good proxy as a third, good page),
and checks each page with the network emulated offline:
  - no console message at all (console API, exceptions, browser log entries);
  - no request but the page itself (data: URLs excepted): everything is embedded;
  - the view was built (<html data-view3d="ready">) and the canvas is not blank: its screenshot
    has more than one colour, and at least 1 % of its pixels differ from the most common one;
  - the HM' layer (what breaks the outside claim) is marked as breaking it, on, and shows zero
    segments for the good proxy, a non-zero number (counted, drawn, red pixels in the view) for
    the defect.
First the checker runs on copies of the good page with one planted problem each (a console
message, a hidden canvas, a request to a CDN, no WebGL) and on each page with the other page's
expectation; it must find every one: a checker that finds nothing proves nothing.

usage: proxy_check_view3d.py BIN_DIR DATA_DIR WORK_DIR [--screenshot PNG]
Exit 0 pass, 1 fail, 77 skip (Chromium is not installed).
"""
import base64
import json
import os
import shutil
import struct
import subprocess
import sys
import time
import urllib.parse

from headless_chromium import CHROMIUM_NAMES, Browser, png_pixels

RAYS = "200000"
RED_PIXELS = 20  # fewer: no HM' line is drawn
SCALE = 0.5  # of the canvas screenshot (a pure-Python PNG decoder reads it)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(cmd, expect_code):
    start = time.monotonic()
    result = subprocess.run(cmd, capture_output=True, text=True, timeout=240)
    if result.returncode != expect_code:
        fail(f"{' '.join(cmd)}: exit {result.returncode}, expected {expect_code}\n"
             f"stdout:\n{result.stdout[-3000:]}\nstderr:\n{result.stderr[-3000:]}")
    return result, time.monotonic() - start


# --- meshes ----------------------------------------------------------------------------------

def read_ply(path):
    """Vertices and faces of a PLY with float x y z and a face list (ASCII or binary LE)."""
    with open(path, "rb") as f:
        data = f.read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode("ascii").splitlines()
    fmt = header[1].split()[1]
    elements, current = [], None
    for line in header:
        words = line.split()
        if words[0] == "element":
            current = [words[1], int(words[2]), []]
            elements.append(current)
        elif words[0] == "property":
            current[2].append(words[1:])
    types = {"char": "b", "int8": "b", "uchar": "B", "uint8": "B", "short": "h", "int16": "h",
             "ushort": "H", "uint16": "H", "int": "i", "int32": "i", "uint": "I", "uint32": "I",
             "float": "f", "float32": "f", "double": "d", "float64": "d"}
    vertices, faces = [], []
    if fmt == "ascii":
        values = iter(data[end:].split())
        for name, count, props in elements:
            for _ in range(count):
                row = []
                for p in props:
                    if p[0] == "list":
                        row.append([int(next(values)) for _ in range(int(next(values)))])
                    else:
                        row.append(float(next(values)))
                (vertices if name == "vertex" else faces).append(
                    row[:3] if name == "vertex" else row[0])
        return vertices, faces
    if fmt != "binary_little_endian":
        fail(f"{path}: PLY format {fmt} not handled by the test's reader")
    at = end
    for name, count, props in elements:
        for _ in range(count):
            row = []
            for p in props:
                if p[0] == "list":
                    n, = struct.unpack_from("<" + types[p[1]], data, at)
                    at += struct.calcsize(types[p[1]])
                    item = "<%d%s" % (n, types[p[2]])
                    row.append(list(struct.unpack_from(item, data, at)))
                    at += struct.calcsize(item)
                else:
                    v, = struct.unpack_from("<" + types[p[0]], data, at)
                    at += struct.calcsize(types[p[0]])
                    row.append(v)
            if name == "vertex":
                vertices.append(row[:3])
            elif name == "face":
                faces.append(row[0])
    return vertices, faces


def write_ply(path, vertices, faces):
    with open(path, "w", encoding="ascii") as f:
        f.write(f"ply\nformat ascii 1.0\nelement vertex {len(vertices)}\nproperty float x\n"
                f"property float y\nproperty float z\nelement face {len(faces)}\n"
                "property list uchar int vertex_indices\nend_header\n")
        for v in vertices:
            f.write("%.9g %.9g %.9g\n" % tuple(v))
        for face in faces:
            f.write("%d %s\n" % (len(face), " ".join(map(str, face))))


def scaled_copy(source, target, factor):
    """The planted defect: `source` scaled by `factor` about the centre of its box."""
    vertices, faces = read_ply(source)
    lo = [min(v[a] for v in vertices) for a in range(3)]
    hi = [max(v[a] for v in vertices) for a in range(3)]
    centre = [(lo[a] + hi[a]) / 2 for a in range(3)]
    write_ply(target, [[centre[a] + factor * (v[a] - centre[a]) for a in range(3)]
                       for v in vertices], faces)


# --- PNG -------------------------------------------------------------------------------------

FINDINGS_SCRIPT = """(() => {
  const canvas = document.querySelector('#viewport canvas');
  const r = canvas ? canvas.getBoundingClientRect() : null;
  const layers = {};
  for (const label of document.querySelectorAll('label.layer')) {
    const box = label.querySelector('input');
    layers[label.dataset.layer] = {
      counted: label.dataset.counted === undefined ? null : Number(label.dataset.counted),
      drawn: label.dataset.drawn === undefined ? null : Number(label.dataset.drawn),
      checked: box.checked, breaks: label.classList.contains('breaks')};
  }
  return {state: document.documentElement.dataset.view3d || '',
          status: document.getElementById('view3d-status').textContent,
          view: window.pvView3d || null, layers,
          // The canvas less 2 px on each side: its frame's border is not the view.
          canvas: r ? {x: r.left + scrollX + 2, y: r.top + scrollY + 2, width: r.width - 4,
                       height: r.height - 4} : null};
})()"""


def open_page(browser, page, screenshot=None):
    """Loads `page` offline in a new tab; returns (findings, console lines, requests, pixels)."""
    target = browser.send("Target.createTarget", {"url": "about:blank"})["targetId"]
    session = browser.send("Target.attachToTarget", {"targetId": target, "flatten": True})[
        "sessionId"]
    first_event = len(browser.events)
    for domain in ("Runtime", "Log", "Network", "Page"):
        browser.send(domain + ".enable", session=session)
    browser.send("Network.emulateNetworkConditions",
                 {"offline": True, "latency": 0, "downloadThroughput": -1,
                  "uploadThroughput": -1}, session=session)
    url = "file://" + urllib.parse.quote(os.path.abspath(page))
    browser.send("Page.navigate", {"url": url}, session=session)
    findings, deadline = {}, time.monotonic() + 20
    while time.monotonic() < deadline:
        result = browser.send("Runtime.evaluate", {"expression": FINDINGS_SCRIPT,
                                                    "returnByValue": True}, session=session)
        findings = result.get("result", {}).get("value") or {}
        if findings.get("state") in ("ready", "failed"):
            break
        browser.pump(0.1)
    pixels = None
    canvas = findings.get("canvas")
    if findings.get("state") == "ready" and canvas and canvas["width"] > 0:
        shot = browser.send("Page.captureScreenshot", {
            "format": "png", "captureBeyondViewport": True,
            "clip": dict(canvas, scale=SCALE)}, session=session)
        png = base64.b64decode(shot["data"])
        if screenshot:
            with open(screenshot, "wb") as f:
                f.write(png)
        try:
            pixels = png_pixels(png)
        except ValueError as e:
            fail(str(e))
    browser.pump(0.2)
    console, requests = [], []
    for event in browser.events[first_event:]:
        if event.get("sessionId") != session:
            continue
        method, params = event.get("method"), event.get("params", {})
        if method == "Runtime.consoleAPICalled":
            console.append(f"console.{params['type']}: " + " ".join(
                str(a.get("value", a.get("description", ""))) for a in params.get("args", [])))
        elif method == "Runtime.exceptionThrown":
            details = params.get("exceptionDetails", {})
            console.append("exception: " + details.get("exception", {}).get(
                "description", details.get("text", "")))
        elif method == "Log.entryAdded":
            entry = params["entry"]
            console.append(f"log {entry['level']} ({entry['source']}): {entry['text']}")
        elif method == "Network.requestWillBeSent":
            request_url = params["request"]["url"]
            if request_url != url and not request_url.startswith("data:"):
                requests.append(request_url)
    browser.send("Target.closeTarget", {"targetId": target})
    return findings, console, requests, pixels


def look(browser, page, screenshot=None):
    """What `page` shows in the browser: its findings (state, layers, view, canvas pixel
    statistics), console lines and requests."""
    findings, console, requests, pixels = open_page(browser, page, screenshot)
    findings["console"], findings["requests"] = console, requests
    if pixels:
        width, height, colours = pixels
        counts = {}
        for c in colours:
            counts[c] = counts.get(c, 0) + 1
        findings["pixels"] = {
            "width": width, "height": height, "colours": len(counts),
            "not_dominant": round(1 - max(counts.values()) / len(colours), 4),
            "red": sum(n for (r, g, b), n in counts.items() if r > 120 and r > 2 * g and r > 2 * b)}
    return findings


def judge(findings, expect_errors):
    """Failures of a page from its findings: console, requests, a blank or missing view, and the
    HM' layer (zero segments when expect_errors is False, some when True)."""
    failures = ["console message: " + c for c in findings["console"]]
    failures += ["network request: " + r for r in findings["requests"]]
    if findings.get("state") != "ready" or "pixels" not in findings:
        failures.append("the 3D view was not built (data-view3d=%r): %s" % (
            findings.get("state"), findings.get("status", "").strip()))
        return failures
    pixels = findings["pixels"]
    if pixels["colours"] < 2 or pixels["not_dominant"] < 0.01:
        failures.append(f"the canvas is blank: {pixels['colours']} colour(s), "
                        f"{pixels['not_dominant']:.2%} of the pixels differ from the most common one")
    hm = findings.get("layers", {}).get("hm")
    view_hm = ((findings.get("view") or {}).get("layers") or {}).get("hm") or {}
    red = pixels["red"]
    if not hm or not hm["breaks"] or not hm["checked"] or not view_hm.get("visible"):
        failures.append(f"the HM' layer is missing, not marked as breaking the outside claim, or "
                        f"not shown: {hm}, {view_hm}")
    elif expect_errors:
        if hm["counted"] == 0 or hm["drawn"] == 0 or view_hm.get("drawn", 0) == 0:
            failures.append(f"the HM' layer shows no segments: {hm}")
        if red < RED_PIXELS:
            failures.append(f"no red HM' lines in the view ({red} red pixels)")
    else:
        if hm["counted"] != 0 or hm["drawn"] != 0:
            failures.append(f"the HM' layer shows segments for a proxy without any: {hm}")
        if red >= RED_PIXELS:
            failures.append(f"{red} red pixels in the view of a proxy without HM' segments")
    return failures


def plant(page, folder, name, old, new):
    with open(page, encoding="utf-8") as f:
        text = f.read()
    if old not in text:
        fail(f"cannot plant '{name}': '{old}' is not in the page")
    path = os.path.join(folder, f"planted_{name}.html")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace(old, new, 1))
    return path


def write_pages(bin_dir, data_dir, work):
    """The pages to look at: proxy-check --html of a good outside proxy and of a defect one
    (scaled by 0.9: it breaks the class), and proxy-gen --report's page of the good one."""
    proxy_gen = os.path.join(bin_dir, "proxy-gen")
    proxy_check = os.path.join(bin_dir, "proxy-check")
    bunny = os.path.join(data_dir, "bunny.off")
    good_proxy = os.path.join(work, "bunny.outside.ply")
    # proxy-gen --report writes the same kind of page for the proxy it makes: judged as a good one.
    gen_page = os.path.join(work, "proxy_gen.html")
    _, t_gen = run([proxy_gen, bunny, "--kind", "outside", "-o", good_proxy, "--quiet",
                    "--report", gen_page, "--check-rays", RAYS, "--seed", "1"], 0)
    bad_proxy = os.path.join(work, "bunny.shrunk.ply")
    scaled_copy(good_proxy, bad_proxy, 0.9)
    good, bad = os.path.join(work, "good.html"), os.path.join(work, "defect.html")
    common = ["--rays", RAYS, "--seed", "1", "--expect", "outside", "--quiet"]
    _, t_good = run([proxy_check, bunny, good_proxy, "--html", good,
                     "--json", os.path.join(work, "good.json")] + common, 0)
    # The defect contradicts --expect outside (exit 1); the page is written all the same.
    _, t_bad = run([proxy_check, bunny, bad_proxy, "--html", bad,
                    "--json", os.path.join(work, "defect.json")] + common, 1)
    with open(os.path.join(work, "good.json")) as f:
        good_json = json.load(f)
    with open(good, "rb") as f:
        good_bytes = f.read()
    import hashlib
    if good_json.get("html", {}).get("sha256") != hashlib.sha256(good_bytes).hexdigest():
        fail("the JSON does not record the page's sha256")
    with open(os.path.join(work, "defect.json")) as f:
        if json.load(f)["counts"]["HM"] == 0:
            fail("the planted defect (proxy scaled by 0.9) shows no HM' segment")
    print(f"proxy-gen {t_gen:.1f} s, proxy-check good {t_good:.1f} s, defect {t_bad:.1f} s; "
          f"page {len(good_bytes) / 1e6:.2f} MB")
    return good, bad, gen_page


def main():
    args = sys.argv[1:]
    screenshot = None
    if "--screenshot" in args:
        i = args.index("--screenshot")
        screenshot = args[i + 1]
        del args[i:i + 2]
    if len(args) != 3:
        print(__doc__)
        return 2
    bin_dir, data_dir, work = args
    chromium = next((shutil.which(n) for n in CHROMIUM_NAMES if shutil.which(n)), None)
    if not chromium:
        print("SKIP: Chromium is not installed")
        return 77
    start = time.monotonic()
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    good, bad, gen_page = write_pages(bin_dir, data_dir, work)

    browser = Browser(chromium, work)
    failed = False
    try:
        t = time.monotonic()
        pages = {"good": look(browser, good, screenshot), "defect": look(browser, bad),
                 "proxy-gen": look(browser, gen_page)}
        print(f"good and defect pages looked at in {time.monotonic() - t:.1f} s")
        # The checker first: each planted problem must be found.
        planted = [
            ("console", plant(good, work, "console", "<head>",
                              "<head><script>console.log('planted');</script>"),
             False, "console message"),
            ("blank", plant(good, work, "blank", "</style>",
                            "#viewport canvas { visibility: hidden; }\n</style>"),
             False, "canvas is blank"),
            ("cdn", plant(good, work, "cdn", "</body>",
                          '<script type="module" src="https://unpkg.com/three@0.185.1/build/'
                          'three.module.min.js"></script></body>'),
             False, "network request"),
            ("no_webgl", plant(good, work, "no_webgl", "<head>",
                               "<head><script>HTMLCanvasElement.prototype.getContext = "
                               "() => null;</script>"),
             False, "was not built"),
            ("good_as_defect", "good", True, "HM' layer shows no segments"),
            ("defect_as_good", "defect", False, "HM' layer shows segments"),
        ]
        for name, page, expect_errors, wanted in planted:
            t = time.monotonic()
            findings = pages[page] if page in pages else look(browser, page)
            failures = judge(findings, expect_errors)
            if not any(wanted in f for f in failures):
                print(f"FAIL: the checker misses the planted problem '{name}' ({wanted}); "
                      f"it found: {failures}")
                failed = True
            else:
                print(f"planted '{name}' found ({time.monotonic() - t:.1f} s): "
                      + next(f for f in failures if wanted in f)[:150])
        for name, expect_errors in (("good", False), ("defect", True), ("proxy-gen", False)):
            findings = pages[name]
            failures = judge(findings, expect_errors)
            for f in failures:
                print(f"FAIL: {name} page: {f}")
            failed = failed or bool(failures)
            view = findings.get("view") or {}
            print(f"{name} page: layers {findings.get('layers')}; "
                  f"drawn {view.get('triangles')} triangles, {view.get('lines')} lines; "
                  f"canvas {findings.get('pixels')}")
    finally:
        browser.close()
    print(f"total {time.monotonic() - start:.1f} s")
    if failed:
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())

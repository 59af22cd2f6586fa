#!/usr/bin/env python3
"""The HTML report as a browser shows it: renders a tiny report with render-compare and opens
report.html in headless Chromium at 800 px width. Fails on a console message, an image that does
not load, a link or image naming a file the run did not write, and a horizontal scroll.

First the checker is run on a copy of the page with one defect of each kind planted, and must find
each of them: a checker that finds nothing proves nothing.

usage: report_page_test.py RENDER_COMPARE SCENES_DIR WORK_DIR
Exit 0 pass, 1 fail, 77 skip (Chromium is not installed).
"""
import html.parser
import json
import os
import re
import shutil
import subprocess
import sys
import urllib.parse

WIDTH = 800
RESULT_ID = "pv-page-check"

# Injected first into <head> of a copy of the page: records errors while the page loads, then
# sends its findings to the frames page.
CHECK_SCRIPT = """<script>
(function () {
  var failures = [];
  window.addEventListener('error', function (e) {
    var t = e.target;
    failures.push(t && t !== window && (t.src || t.href)
                  ? 'resource failed to load: ' + (t.src || t.href)
                  : 'script error: ' + e.message);
  }, true);
  window.addEventListener('load', function () {
    var imgs = document.images, n = 0;
    for (var i = 0; i < imgs.length; ++i) {
      if (imgs[i].id === 'pv-no-check') continue;
      ++n;
      if (!imgs[i].complete || imgs[i].naturalWidth === 0)
        failures.push('image does not load: ' + imgs[i].getAttribute('src'));
    }
    var root = document.documentElement;
    if (root.scrollWidth > %(width)d || root.scrollWidth > root.clientWidth)
      failures.push('horizontal scroll: page ' + root.scrollWidth + ' px wide, window ' +
                    root.clientWidth + ' px');
    parent.postMessage({page: location.pathname.split('/').pop(), images: n,
                        failures: failures}, '*');
  });
})();
</script>""" % {"width": WIDTH}

# Opens every checked copy in an iframe of the page's width (one Chromium start for all of them:
# it costs seconds) and writes their findings into the DOM that --dump-dom prints.
FRAMES_PAGE = """<!DOCTYPE html><html><head><meta charset="utf-8"></head><body>
<pre id="%(id)s"></pre>
<script>
var results = {};
window.addEventListener('message', function (e) {
  results[e.data.page] = e.data;
  if (Object.keys(results).length === %(count)d)
    document.getElementById('%(id)s').textContent = JSON.stringify(results);
});
</script>
%(frames)s
</body></html>"""


class References(html.parser.HTMLParser):
    """The href of every <a> and the src of every <img> of a page."""

    def __init__(self):
        super().__init__()
        self.links, self.images = [], []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        if tag == "a" and "href" in a:
            self.links.append(a["href"])
        if tag == "img" and "src" in a:
            self.images.append(a["src"])


def missing_files(page_text, folder):
    """References of the page to files that do not exist in `folder` (or leave it)."""
    refs = References()
    refs.feed(page_text)
    bad = []
    for ref in refs.links + refs.images:
        parsed = urllib.parse.urlparse(ref)
        if parsed.scheme or ref.startswith(("/", "#")):
            bad.append(f"not a relative link to a written file: {ref}")
            continue
        path = os.path.normpath(os.path.join(folder, urllib.parse.unquote(parsed.path)))
        if not path.startswith(os.path.abspath(folder) + os.sep) or not os.path.isfile(path):
            bad.append(f"link to a file the run did not write: {ref}")
    return bad, len(refs.links), len(refs.images)


def check_pages(chromium, pages):
    """Opens every page of `pages` (all in one folder) in Chromium; returns for each
    (failures, number of images checked, number of links)."""
    folder = os.path.dirname(os.path.abspath(pages[0]))
    results, copies = {}, {}
    for page in pages:
        with open(page, encoding="utf-8") as f:
            text = f.read()
        failures, n_links, _ = missing_files(text, folder)
        results[page] = (failures, 0, n_links)
        copies[page] = os.path.join(folder, ".page_check_" + os.path.basename(page))
        with open(copies[page], "w", encoding="utf-8") as f:
            f.write(text.replace("<head>", "<head>" + CHECK_SCRIPT, 1))
    frames_page = os.path.join(folder, ".page_check_frames.html")
    with open(frames_page, "w", encoding="utf-8") as f:
        f.write(FRAMES_PAGE % {
            "id": RESULT_ID, "count": len(pages),
            "frames": "\n".join(
                f'<iframe src="{urllib.parse.quote(os.path.basename(c))}" width="{WIDTH}" '
                'height="900"></iframe>' for c in copies.values())})
    profile = os.path.join(folder, ".chromium-profile")
    cmd = [chromium, "--headless", "--disable-gpu", "--no-sandbox", "--no-first-run",
           "--disable-extensions", "--allow-file-access-from-files", f"--user-data-dir={profile}",
           f"--window-size={2 * WIDTH + 100},1000", "--virtual-time-budget=5000",
           "--enable-logging=stderr", "--v=0", "--dump-dom",
           "file://" + urllib.parse.quote(os.path.abspath(frames_page))]
    try:
        run = subprocess.run(cmd, capture_output=True, text=True, timeout=60)
    finally:
        for c in list(copies.values()) + [frames_page]:
            os.remove(c)
        shutil.rmtree(profile, ignore_errors=True)
    match = re.search(r'<pre id="%s">(.*?)</pre>' % RESULT_ID, run.stdout, re.S)
    found = json.loads(html.unescape(match.group(1))) if match and match.group(1) else {}
    for page in pages:
        failures, _, n_links = results[page]
        name = os.path.basename(copies[page])
        # Chromium logs every console message of a page as
        # ...:CONSOLE:line] "text", source: URL (line) (older versions: CONSOLE(line)).
        for line in run.stderr.splitlines():
            if re.search(r":CONSOLE[:(]\d+", line) and urllib.parse.quote(name) in line:
                failures.append("console: " + line.split("] ", 1)[-1])
        if name not in found:
            failures.append(f"Chromium did not run the page's checks (exit {run.returncode}):\n"
                            + run.stderr[-2000:])
            results[page] = (failures, 0, n_links)
            continue
        results[page] = (failures + found[name]["failures"], found[name]["images"], n_links)
    return results


def render_report(render_compare, scenes_dir, work):
    """A box and its box proxy on a ground quad under a quad light, rendered tiny and short."""
    os.makedirs(work, exist_ok=True)
    def box(path, lo, hi):
        v = [(x, y, z) for x in (lo, hi) for y in (lo, hi) for z in (lo, hi)]
        quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
        with open(path, "w") as f:
            f.write(f"OFF\n8 12 0\n")
            f.writelines(f"{x} {y} {z}\n" for x, y, z in v)
            for a, b, c, d in quads:
                f.write(f"3 {a} {b} {c}\n3 {a} {c} {d}\n")
    box(os.path.join(work, "box.off"), 0, 1)
    box(os.path.join(work, "box_outside.off"), -0.1, 1.1)
    scene = {
        "camera": {"eye": [0, 3, 6], "look_at": [0, 0.5, 0], "fov_deg": 40,
                   "resolution": [32, 24]},
        "lights": [{"type": "quad", "corner": [-1, 4, -1], "edge_u": [2, 0, 0],
                    "edge_v": [0, 0, 2], "radiance": [8, 8, 8]}],
        "meshes": [
            {"name": "ground", "file": os.path.join(scenes_dir, "meshes", "ground.obj"),
             "transform": {"scale": 10}},
            {"name": "box", "file": "box.off", "transform": {"translate": [-0.5, 0, -0.5]},
             "proxies": [{"kind": "outside", "method": "box", "file": "box_outside.off",
                          "class": "outside"}]}]}
    scene_path = os.path.join(work, "box-on-ground.json")
    with open(scene_path, "w") as f:
        json.dump(scene, f)
    out = os.path.join(work, "report")
    run = subprocess.run([render_compare, scene_path, "--out", out, "--spp", "1,2",
                          "--equal-time", "0.05", "--seeds", "2", "--reference-spp", "64",
                          "--quiet"], capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        sys.exit(f"FAIL: render-compare exited {run.returncode}\n{run.stderr}")
    return os.path.join(out, "report.html")


def planted_defects_page(page):
    """A copy of `page` with one defect of each kind the checker must find."""
    with open(page, encoding="utf-8") as f:
        text = f.read()
    defects = ('<img src="no_such_image.png" alt="planted">'
               '<a href="no_such_table.csv">planted</a>'
               '<div style="width: 1400px">planted</div>'
               '<script>console.error("planted console error")</script>')
    path = os.path.join(os.path.dirname(page), "planted.html")
    with open(path, "w", encoding="utf-8") as f:
        f.write(text.replace("</body>", defects + "</body>", 1))
    return path


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    render_compare, scenes_dir, work = (os.path.abspath(a) for a in sys.argv[1:])
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if not chromium:
        print("SKIP: Chromium is not installed (Debian package chromium; ./setup.sh installs it)")
        return 77
    shutil.rmtree(work, ignore_errors=True)
    page = render_report(render_compare, scenes_dir, work)

    planted = planted_defects_page(page)
    results = check_pages(chromium, [page, planted])
    os.remove(planted)
    found = results[planted][0]
    expected = ["no_such_image.png", "no_such_table.csv", "horizontal scroll",
                "planted console error"]
    unnoticed = [e for e in expected if not any(e in f for f in found)]
    if unnoticed:
        print("FAIL: the checker misses planted defects: " + ", ".join(unnoticed))
        print("it found:\n  " + "\n  ".join(found))
        return 1

    failures, images, links = results[page]
    if images < 10 or links < 10:
        failures.append(f"only {images} images and {links} links: not the whole report")
    if failures:
        print(f"FAIL: {page}:\n  " + "\n  ".join(failures))
        return 1
    print(f"PASS: {page}: {images} images load, {links} links reach written files, no console "
          f"message, no horizontal scroll at {WIDTH} px")
    return 0


if __name__ == "__main__":
    sys.exit(main())

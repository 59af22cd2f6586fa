#!/usr/bin/env python3
"""Keeps the repository's references to its own documentation true.

Fails (exit 1, one line per finding) when any text file of the repository (build folders and
.git excluded):
  - points outside the repository to the old notes folder or names the old notes file (the
    docs/ folder is the documentation; the patterns are built below so that this file does not
    match itself);
  - refers to a tracker entry by number (the tracker's word for an entry followed by a number
    or by '#');
  - cites docs/<page>.md for a page that does not exist;
  - cites a section of docs/design.md that the page does not have: "docs/design.md §N" (a §
    token in the same sentence), a quoted section name right after the citation
    (docs/design.md ("Error metrics")), "pitfall N" or "costs point N";
  - (Markdown files) links to a local file that does not exist;
  - names a source file by its path from the root (lib/..., proxies/..., apps/..., tests/...,
    bench/..., fuzz/..., docs/...) that does not exist: moved files leave comments and pages
    behind (scenes/ and data/ paths are left out: they are often examples).

Usage: check_docs.py REPO_ROOT      check the repository
       check_docs.py --self-test    plant each kind of mistake in a temporary tree and require
                                    that every one is found (the check can fail)
"""
import os
import re
import sys
import tempfile

# Built from parts so that the checker's own source (and its self-test) holds none of what it
# looks for.
OLD_FOLDER = "../" + "shared"
OLD_NOTES = "DES" + "IGN" + ".md"
TRACKER_WORD = "iss" + "ue"
ISSUE_REF = re.compile(r"\b" + TRACKER_WORD + r"\s*(#\s*\d*|[1-9][0-9]?\b)", re.IGNORECASE)

DOC_CITE = re.compile(r"\bdocs/([A-Za-z0-9_\-]+\.md)")
DESIGN_CITE = re.compile(r"(?:\bdocs/|(?<![\w/.-]))design\.md")
SECTION_TOKEN = re.compile(r"§\s*([0-9]+[a-z]?(?:\.[0-9]+)?)")
QUOTED_NAME = re.compile(r'^\s*\(?\s*"([^"]+)"')
PITFALL = re.compile(r"\bpitfalls?\s+([0-9]+)", re.IGNORECASE)
COST_POINT = re.compile(r"\bcosts?,?\s+points?\s+([0-9]+)", re.IGNORECASE)
MD_LINK = re.compile(r"\]\(([^)\s]+)\)")
REPO_PATH = re.compile(
    r"(?<![\w/.<-])((?:lib|proxies|apps|tests|bench|fuzz|docs)/[\w./-]*\w\.(?:h|cpp|py|cmake|sh|json|txt|drc|ply|obj|off))\b")
COMMENT_JOIN = re.compile(r"\n\s*(?://+|#+|\*+)?\s*")

SKIP_DIRS = {".git", ".cache", "__pycache__", "node_modules"}
MAX_BYTES = 4 << 20


def is_build_dir(path, name):
    return name.startswith("build") or name == "out" or os.path.exists(
        os.path.join(path, "CMakeCache.txt"))


def text_files(root):
    for dirpath, dirnames, filenames in os.walk(root):
        dirnames[:] = sorted(d for d in dirnames if d not in SKIP_DIRS and
                             not is_build_dir(os.path.join(dirpath, d), d))
        for name in sorted(filenames):
            path = os.path.join(dirpath, name)
            if not os.path.isfile(path) or os.path.islink(path):
                continue
            if os.path.samefile(path, __file__):
                continue  # its self-test plants every mistake it looks for
            if os.path.getsize(path) > MAX_BYTES:
                continue
            with open(path, "rb") as f:
                data = f.read()
            if b"\0" in data[:8192]:
                continue  # binary
            yield path, data.decode("utf-8", errors="replace")


class DesignPage:
    """What docs/design.md offers to be cited: § numbers, section names, numbered items."""

    def __init__(self, text):
        self.sections = set()
        self.headings = []
        self.pitfalls = set()
        self.cost_points = set()
        current = ""
        for line in text.splitlines():
            if line.startswith("#"):
                current = line.lstrip("#").strip()
                self.headings.append(current.lower())
                for tok in SECTION_TOKEN.findall(current):
                    self.sections.add(tok)
                continue
            item = re.match(r"\s*([0-9]+)\.\s", line)
            if item:
                if "pitfall" in current.lower():
                    self.pitfalls.add(item.group(1))
                if "measured costs" in current.lower():
                    self.cost_points.add(item.group(1))

    def has_name(self, name):
        name = name.lower()
        return any(name in h for h in self.headings)


def sentence_after(text, end):
    """The rest of the sentence after a citation, with comment prefixes of following lines
    removed, cut at the next citation of a page."""
    window = COMMENT_JOIN.sub(" ", text[end:end + 240])
    cut = len(window)
    for stop in (re.search(r"\.(\s|$)", window), re.search(r"\bdocs/|\]\(", window)):
        if stop:
            cut = min(cut, stop.start())
    return window[:cut]


def line_of(text, pos):
    return text.count("\n", 0, pos) + 1


def check(root):
    root = os.path.abspath(root)
    docs = os.path.join(root, "docs")
    design_path = os.path.join(docs, "design.md")
    design = None
    if os.path.isfile(design_path):
        with open(design_path, encoding="utf-8") as f:
            design = DesignPage(f.read())
    findings = []

    def report(path, pos, text, what):
        findings.append(f"{os.path.relpath(path, root)}:{line_of(text, pos)}: {what}")

    for path, text in text_files(root):
        for needle in (OLD_FOLDER, OLD_NOTES):
            start = 0
            while (pos := text.find(needle, start)) >= 0:
                report(path, pos, text, f"refers to '{needle}' (use docs/ instead)")
                start = pos + 1
        for m in ISSUE_REF.finditer(text):
            report(path, m.start(), text, f"tracker reference '{m.group(0)}'")
        for m in DOC_CITE.finditer(text):
            if not os.path.isfile(os.path.join(docs, m.group(1))):
                report(path, m.start(), text, f"cites docs/{m.group(1)}, which does not exist")
        if design is not None:
            for m in DESIGN_CITE.finditer(text):
                rest = sentence_after(text, m.end())
                for tok in SECTION_TOKEN.findall(rest):
                    if tok not in design.sections:
                        report(path, m.start(), text, f"cites design.md §{tok}, which it lacks")
                q = QUOTED_NAME.match(rest.lstrip(" ,"))
                if q and not design.has_name(q.group(1)):
                    report(path, m.start(), text,
                           f"cites design.md \"{q.group(1)}\", no such section")
                for n in PITFALL.findall(rest):
                    if n not in design.pitfalls:
                        report(path, m.start(), text, f"cites design.md pitfall {n}, which it lacks")
                for n in COST_POINT.findall(rest):
                    if n not in design.cost_points:
                        report(path, m.start(), text,
                               f"cites design.md costs point {n}, which it lacks")
        for m in REPO_PATH.finditer(text):
            if not os.path.exists(os.path.join(root, m.group(1))):
                report(path, m.start(), text, f"names {m.group(1)}, which does not exist")
        if path.endswith(".md"):
            for m in MD_LINK.finditer(text):
                target, _, anchor = m.group(1).partition("#")
                if re.match(r"^[a-z]+:", target):
                    continue  # a URL
                full = os.path.normpath(os.path.join(os.path.dirname(path), target)) \
                    if target else path
                if not os.path.exists(full):
                    report(path, m.start(), text, f"links to {target}, which does not exist")
                elif anchor and full.endswith(".md") and anchor not in anchors_of(full):
                    report(path, m.start(), text,
                           f"links to {target or 'itself'}#{anchor}, no such heading")
    return findings


def slug(heading):
    """The anchor GitHub gives a heading: lower case, punctuation dropped, spaces to '-'."""
    text = re.sub(r"[`*]", "", heading.strip().lower())
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", text)  # a link's text
    return re.sub(r"[^\w\- ]", "", text).replace(" ", "-")


def anchors_of(path):
    anchors, seen, fenced = set(), {}, False
    with open(path, encoding="utf-8", errors="replace") as f:
        for line in f:
            if line.lstrip().startswith("```"):
                fenced = not fenced
            m = re.match(r"#{1,6}\s+(.*?)\s*#*\s*$", line)
            if fenced or not m:
                continue
            base = slug(m.group(1))
            n = seen.get(base, 0)
            seen[base] = n + 1
            anchors.add(base if n == 0 else f"{base}-{n}")
    return anchors


def self_test():
    design = ("# Design\n## §1 Ray classes\n## §2b Measured costs and what follows\n"
              "1. point one\n2. point two\n## §4 Pitfalls\n1. one\n2. two\n")
    planted = {
        "a.cpp": "// see " + OLD_FOLDER + "/data\n",
        "b.h": "// from " + OLD_NOTES + "\n",
        "c.txt": f"fixed in {TRACKER_WORD} 12\n",
        "d.py": f"# {TRACKER_WORD} #7 says so\n",
        "e.cpp": "// docs/missing_page.md explains\n",
        "f.cpp": "// (docs/design.md, §9)\n",
        "g.cpp": "// docs/design.md (\"No such heading\")\n",
        "h.cpp": "// docs/design.md, pitfall 7\n",
        "i.cpp": "// docs/design.md,\n// costs point 5: baseline\n",
        "j.md": "see [x](nowhere.md)\n",
        "k.md": "see [x](docs/design.md#no-such-heading)\n",
        "l.cpp": "// the loop of lib/mesh/moved_away.cpp\n",
    }
    fine = {
        "ok.cpp": "// docs/design.md §2b, pitfall 2, costs point 2; docs/design.md (\"Ray classes\")\n"
                  f"// paper §4 is not ours. Two {TRACKER_WORD}s remain, e.g. the t{TRACKER_WORD} 12.\n",
        "ok.h": "// like ok.cpp and docs/design.md; not ../lib/x.h or my/lib/y.h\n",
        "ok.md": "# A §3 heading (x)\n[d](docs/design.md#2b-measured-costs-and-what-follows), "
                 "[s](#a-3-heading-x) and [u](https://example.org)\n",
    }
    with tempfile.TemporaryDirectory() as tmp:
        os.mkdir(os.path.join(tmp, "docs"))
        with open(os.path.join(tmp, "docs", "design.md"), "w") as f:
            f.write(design)
        os.mkdir(os.path.join(tmp, "build"))
        with open(os.path.join(tmp, "build", "ignored.cpp"), "w") as f:
            f.write(f"{TRACKER_WORD} 3\n")
        for name, body in {**planted, **fine}.items():
            with open(os.path.join(tmp, name), "w") as f:
                f.write(body)
        findings = check(tmp)
    failed = False
    for name in planted:
        if not any(x.startswith(name + ":") for x in findings):
            print(f"self-test: the mistake planted in {name} was not found")
            failed = True
    for x in findings:
        if x.split(":")[0] not in planted:
            print(f"self-test: false finding: {x}")
            failed = True
    print("self-test:", "FAILED" if failed else f"ok ({len(findings)} planted findings found)")
    return 1 if failed else 0


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    if sys.argv[1] == "--self-test":
        return self_test()
    findings = check(sys.argv[1])
    for x in findings:
        print(x)
    print(f"{len(findings)} finding(s)")
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main())

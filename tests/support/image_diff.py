"""Pixel comparisons of image pairs in one oiiotool process: every OpenImageIO start costs about
half a second here (it loads some 250 shared libraries), and the tests compare dozens of pairs.
"""
import re
import subprocess

_SECTION = re.compile(r'^Computing diff of "(.*)" vs "(.*)"$')


def differing_pairs(pairs, tolerance=0.0, channels=None):
    """The pairs (a, b) whose pixels differ by more than `tolerance` in any channel (0: bit for
    bit), each with oiiotool's report; channels="R,G,B" compares only those. Raises RuntimeError
    when oiiotool does not report on every pair (an unreadable file, a size mismatch)."""
    pairs = list(pairs)
    if not pairs:
        return []
    args = ["oiiotool", "--fail", repr(tolerance), "--failpercent", "0", "--warn", repr(tolerance)]
    select = ["--ch", channels] if channels else []
    for a, b in pairs:
        args += [str(a), *select, str(b), *select, "--diff", "--pop", "--pop"]
    p = subprocess.run(args, capture_output=True, text=True)
    reports, current = [], None
    for line in p.stdout.splitlines():
        m = _SECTION.match(line)
        if m:
            current = [m.group(1), m.group(2), []]
            reports.append(current)
        elif current is not None:
            current[2].append(line)
    if len(reports) != len(pairs):
        raise RuntimeError(f"oiiotool reported on {len(reports)} of {len(pairs)} pairs "
                           f"(exit {p.returncode}):\n{p.stdout}\n{p.stderr}")
    differing = []
    for (a, b), (ra, rb, lines) in zip(pairs, reports):
        if (ra, rb) != (str(a), str(b)):
            raise RuntimeError(f"oiiotool's reports are out of order: {ra} vs {rb} for {a} vs {b}")
        if not lines or lines[-1].strip() != "PASS":
            differing.append((a, b, "\n".join(lines)))
    return differing

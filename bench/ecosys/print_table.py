#!/usr/bin/env python3
"""Prints the rows bench_ecosys_ceiling appended to a TSV file (--tsv) as two Markdown tables:
every shading point per light and for the light mix, then the mix split by surface (terrain,
plants) and the whole mix with learning regions split by surface. Later rows of the same variant and light replace earlier ones.

usage: print_table.py RESULTS.tsv
"""
import sys

FIELDS = ["variant", "class", "light", "proxy_tris", "share", "p0", "p_mh", "p_hm", "var",
          "cp0", "cp1", "co0", "co1", "q1", "ceil_rays", "ceil_render", "roul_regions",
          "regions", "c_s", "ceil_heldout"]


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    rows = {}
    with open(sys.argv[1]) as f:
        for line in f:
            r = dict(zip(FIELDS, line.rstrip("\n").split("\t")))
            rows[(r["variant"], r["light"])] = r
    head = ("| variant | class | proxy triangles | light | P(V'=0) | P(MH') | P(HM') | mean V(1-V) "
            "| c_p 0 / 1 (ns) | c_o 0 / 1 (ns) | q=1 | ceiling rays | ceiling render | held-out rays |\n"
            "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")

    def line(r):
        return (f"| {r['variant']} | {r['class']} | {int(r['proxy_tris']):,} | {r['light']} "
                f"| {r['p0']} | {r['p_mh']} | {r['p_hm']} | {r['var']} "
                f"| {float(r['cp0']):.0f} / {float(r['cp1']):.0f} "
                f"| {float(r['co0']):.0f} / {float(r['co1']):.0f} "
                f"| {r['q1']} | {r['ceil_rays']} | {r['ceil_render']} | {r['ceil_heldout']} |")

    print(head)
    for (variant, light), r in rows.items():
        if " on " not in light and "split" not in light:
            print(line(r))
    print()
    print(head)
    for (variant, light), r in rows.items():
        if light.startswith("mix on ") or "split" in light:
            print(line(r))


if __name__ == "__main__":
    main()

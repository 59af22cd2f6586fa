#!/usr/bin/env python3
"""Where a build's time goes, read from ninja's own log and build file.

    scripts/build_times.py [BUILD_DIR] [--jobs N] [--top K] [--json FILE]

For the last build recorded in BUILD_DIR/.ninja_log (default build/) it prints:
- the wall time of that build, the compiler and linker time summed over its steps, and how busy
  the cores were;
- the K slowest steps (translation units and links) and the time per CMake target;
- the critical path: the longest chain of steps that must run one after another (a link waits
  for its objects and libraries), its length, and its steps;
- the wall time a build with N parallel jobs needs at least (the larger of the critical path and
  the summed time over N), and the time ninja's own order takes on N jobs, replayed with the
  measured step times.

A step's time is what ninja logged, so it includes a compiler cache's hits (near zero) and any
other load on the machine: measure from a cold cache on an idle machine (CCACHE_DISABLE=1).
"""
import argparse
import heapq
import json
import os
import re
import sys


def read_log(build_dir):
    """The steps of the newest build in .ninja_log: {output: (start_ms, end_ms)}.

    ninja appends one line per step as it finishes, so within one build the end times never
    decrease; a later build restarts the clock at 0, so a line that ends before the previous
    one begins a new build."""
    path = os.path.join(build_dir, ".ninja_log")
    with open(path) as f:
        header = f.readline()
        if not header.startswith("# ninja log v"):
            sys.exit(f"build_times: {path}: not a ninja log (first line {header.strip()!r})")
        runs, current, last_end = [], {}, -1
        for line in f:
            parts = line.rstrip("\n").split("\t")
            if len(parts) < 4:
                continue
            start, end, out = int(parts[0]), int(parts[1]), parts[3]
            if end < last_end and current:
                runs.append(current)
                current = {}
            last_end = end
            current[out] = (start, end)
        if current:
            runs.append(current)
    if not runs:
        sys.exit(f"build_times: {path}: no build recorded")
    return runs[-1]


def unescape(token):
    return re.sub(r"\$(.)", r"\1", token)


def read_edges(build_dir):
    """The build edges of build.ninja: {output: [inputs]} (explicit, implicit and order-only
    inputs alike: each must be done before the edge starts), followed into subninja files."""
    edges = {}

    def parse(path):
        with open(path) as f:
            text = f.read().replace("$\n", " ")
        for line in text.split("\n"):
            if line.startswith("subninja ") or line.startswith("include "):
                parse(os.path.join(build_dir, unescape(line.split(None, 1)[1].strip())))
                continue
            if not line.startswith("build "):
                continue
            # "build OUTS: RULE INS | IMPLICIT || ORDER_ONLY", where "$:" is an escaped ':'.
            m = re.match(r"((?:[^:$]|\$.)*):(.*)", line[6:])
            if not m:
                continue
            outs = [unescape(t) for t in re.split(r"(?<!\$) +", m.group(1).strip()) if t and t != "|"]
            rest = re.split(r"(?<!\$) +", m.group(2).strip())
            ins = [unescape(t) for t in rest[1:] if t and t not in ("|", "||", "|@")]
            for out in outs:
                edges[out] = ins

    parse(os.path.join(build_dir, "build.ninja"))
    return edges


def target_of(output):
    """The CMake target an output belongs to: 'dir/CMakeFiles/NAME.dir/x.cpp.o' -> NAME; a linked
    file -> its file name without lib prefix and suffix."""
    m = re.search(r"CMakeFiles/([^/]+)\.dir/", output)
    if m:
        return m.group(1)
    name = os.path.basename(output)
    name = re.sub(r"^lib", "", name)
    return re.sub(r"\.(a|so.*)$", "", name)


def critical_path(steps, edges):
    """The longest chain of timed steps through the dependency graph: (seconds, [outputs])."""
    memo = {}

    def longest(node, stack=()):
        if node in memo:
            return memo[node]
        best = (0.0, [])
        for dep in edges.get(node, []):
            if dep in stack:
                continue
            cand = longest(dep, stack + (node,))
            if cand[0] > best[0]:
                best = cand
        own = steps.get(node)
        t = (own[1] - own[0]) / 1000.0 if own else 0.0
        memo[node] = (best[0] + t, best[1] + ([node] if own else []))
        return memo[node]

    sys.setrecursionlimit(100000)
    result = (0.0, [])
    for out in steps:
        cand = longest(out)
        if cand[0] > result[0]:
            result = cand
    return result


def replay(steps, edges, jobs):
    """The wall time of the build's steps on `jobs` workers with the measured step times, each
    step starting as soon as a worker is free and its timed inputs are done, in the order ninja
    started them (ninja's own order: the log's start times)."""
    timed_deps = {}

    def deps_of(node, seen):
        out = set()
        for dep in edges.get(node, []):
            if dep in seen:
                continue
            seen.add(dep)
            if dep in steps:
                out.add(dep)
            else:
                out |= deps_of(dep, seen)
        return out

    for out in steps:
        timed_deps[out] = deps_of(out, set())
    order = sorted(steps, key=lambda o: steps[o][0])
    done_at, workers, pending = {}, [0.0] * jobs, list(order)
    while pending:
        # The first pending step (ninja's order) whose inputs are done soonest after a worker frees.
        free = heapq.heappop(workers)
        best, best_start = None, None
        for out in pending:
            if all(d in done_at for d in timed_deps[out]):
                ready = max([done_at[d] for d in timed_deps[out]], default=0.0)
                start = max(free, ready)
                if best is None or start < best_start:
                    best, best_start = out, start
                if start <= free:
                    break
        pending.remove(best)
        dur = (steps[best][1] - steps[best][0]) / 1000.0
        done_at[best] = best_start + dur
        heapq.heappush(workers, done_at[best])
    return max(done_at.values(), default=0.0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("build_dir", nargs="?", default="build")
    ap.add_argument("--jobs", type=int, default=os.cpu_count() or 2)
    ap.add_argument("--top", type=int, default=15)
    ap.add_argument("--json", help="also write the figures as JSON here")
    args = ap.parse_args()

    steps = read_log(args.build_dir)
    edges = read_edges(args.build_dir)
    secs = {o: (e - s) / 1000.0 for o, (s, e) in steps.items()}
    wall = (max(e for _, e in steps.values()) - min(s for s, _ in steps.values())) / 1000.0
    total = sum(secs.values())
    compile_total = sum(t for o, t in secs.items() if o.endswith(".o"))
    per_target = {}
    for o, t in secs.items():
        per_target[target_of(o)] = per_target.get(target_of(o), 0.0) + t
    cp_len, cp_steps = critical_path(steps, edges)
    bound = max(cp_len, total / args.jobs)
    replayed = replay(steps, edges, args.jobs)

    print(f"build {args.build_dir}: {len(steps)} steps, wall {wall:.0f} s")
    print(f"  summed step time {total:.0f} s (compiles {compile_total:.0f} s, "
          f"links and other {total - compile_total:.0f} s); cores busy {total / wall:.2f} on average")
    print(f"  critical path {cp_len:.0f} s over {len(cp_steps)} steps; "
          f"at {args.jobs} jobs at least {bound:.0f} s, ninja's order replayed {replayed:.0f} s")
    print(f"\nslowest {args.top} steps (s):")
    for o, t in sorted(secs.items(), key=lambda kv: -kv[1])[: args.top]:
        print(f"  {t:7.1f}  {o}")
    print(f"\nslowest {args.top} targets, summed over their steps (s):")
    for name, t in sorted(per_target.items(), key=lambda kv: -kv[1])[: args.top]:
        print(f"  {t:7.1f}  {name}")
    print("\ncritical path (s, in build order):")
    for o in cp_steps:
        print(f"  {secs[o]:7.1f}  {o}")
    if args.json:
        with open(args.json, "w") as f:
            json.dump({
                "build_dir": args.build_dir, "steps": len(steps), "wall_seconds": wall,
                "summed_seconds": total, "compile_seconds": compile_total,
                "critical_path_seconds": cp_len, "critical_path": cp_steps,
                "jobs": args.jobs, "lower_bound_seconds": bound, "replayed_seconds": replayed,
                "targets": dict(sorted(per_target.items(), key=lambda kv: -kv[1])),
                "step_seconds": dict(sorted(secs.items(), key=lambda kv: -kv[1])),
            }, f, indent=1)


if __name__ == "__main__":
    main()

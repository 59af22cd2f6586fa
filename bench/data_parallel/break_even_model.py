"""The break-even alpha of a series of relative efficiencies over a latency sweep, measured
(interpolated in log alpha between sweep points) and extrapolated from one run by the
alpha-beta model; bench_break_even.py --self-test checks both."""
import math
import sys

BASELINE = ("instance-boxes", "exact")
SERIES = [("instance-boxes", "roulette"), ("proxies", "exact"), ("proxies", "roulette")]


def break_even(alphas, values, threshold=1.0):
    """The break-even alpha of one series: the smallest alpha from which `values` (relative
    efficiency at each of the ascending `alphas`) is >= threshold and stays >= threshold for every
    larger alpha of the sweep.

    Returns (kind, alpha):
      ("always", alphas[0])  every value is >= threshold (break-even at or below the sweep);
      ("never", None)        the value at the largest alpha is < threshold;
      ("at", a)              otherwise: with i the last index whose value is < threshold, a is
                             where the straight line through (log alphas[i], values[i]) and
                             (log alphas[i+1], values[i+1]) crosses threshold (so
                             alphas[i] < a <= alphas[i+1]).
    A value of None (a missing run) counts as below the threshold."""
    if len(alphas) != len(values) or not alphas:
        raise ValueError("break_even: alphas and values must be non-empty and of equal length")
    if any(b <= a for a, b in zip(alphas, alphas[1:])):
        raise ValueError("break_even: alphas must ascend")
    below = [i for i, v in enumerate(values) if v is None or v < threshold]
    if not below:
        return "always", alphas[0]
    i = below[-1]
    if i == len(values) - 1:
        return "never", None
    v0, v1 = values[i], values[i + 1]
    if v0 is None:
        return "at", alphas[i + 1]
    t = (threshold - v0) / (v1 - v0)  # v1 >= threshold > v0, so 0 < t <= 1
    la = math.log(alphas[i]) + t * (math.log(alphas[i + 1]) - math.log(alphas[i]))
    return "at", math.exp(la)


def extrapolated_break_even(base, row):
    """The alpha at which `row` would break even with `base` in the alpha-beta model, from one
    run's figures of both (report.json rows: mse, network_alpha_us, modelled_compute_seconds,
    modelled_message_seconds, modelled_control_seconds): each row's modelled time is taken as
    c + alpha x k, with c its modelled compute and k its message and control seconds / alpha
    (the bytes / beta share counts in k: negligible at a large alpha, so pass the largest
    alpha's run). Forward counts are held at that run's (roulette's vary with alpha).

    Returns ("at", a), ("always", 0.0) when the row wins at every alpha >= 0, or ("never", None)
    when it loses at every alpha >= 0 (or wins only below some alpha)."""
    alpha = row["network_alpha_us"]

    def ck(r):
        return (r["modelled_compute_seconds"],
                (r["modelled_message_seconds"] + r["modelled_control_seconds"]) / alpha)
    c_b, k_b = ck(base)
    c_r, k_r = ck(row)
    n = row["mse"] * c_r - base["mse"] * c_b  # the row's excess cost at alpha 0
    d = base["mse"] * k_b - row["mse"] * k_r  # what the row saves per us of alpha
    if n <= 0 and d >= 0:
        return "always", 0.0
    if d <= 0:
        return "never", None
    return "at", n / d


def describe_break_even(result):
    kind, a = result
    if kind == "always":
        return f"always (<= {a:g} us)"
    if kind == "never":
        return "never (in the sweep)"
    return f"{a:.3g} us"


def self_test():
    cases = [
        # (alphas, values, expected kind, expected alpha)
        ([1, 10, 100, 1000], [0.5, 0.8, 1.2, 1.5], "at", math.sqrt(10 * 100)),
        ([1, 10, 100], [1.0, 1.1, 3.0], "always", 1),
        ([1, 10, 100], [1.5, 1.2, 0.9], "never", None),
        ([1, 10, 100, 1000], [1.2, 0.9, 1.1, 1.3], "at", 10 ** 1.5),  # a dip: after it
        ([1, 10, 100], [0.5, 1.0, 1.2], "at", 10),  # exactly 1 counts as break-even
        ([1, 100], [0.0, 2.0], "at", 10),  # halfway in log alpha
        ([1, 10, 100], [0.5, None, 1.5], "at", 100),  # a missing run is not >= 1
        ([0.5, 1.6, 5, 20, 50, 200, 500], [0.6, 0.62, 0.7, 0.9, 1.3, 2.5, 4], "at",
         math.exp(math.log(20) + 0.25 * math.log(50 / 20))),
    ]
    failed = 0
    for alphas, values, kind, alpha in cases:
        got = break_even(alphas, values)
        ok = got[0] == kind and (alpha is None and got[1] is None or
                                 alpha is not None and abs(got[1] - alpha) <= 1e-9 * alpha)
        if not ok:
            failed += 1
            print(f"FAIL: break_even({alphas}, {values}) = {got}, expected ({kind!r}, {alpha})")
    def row(mse, compute, per_alpha, alpha=100.0):
        return {"mse": mse, "network_alpha_us": alpha, "modelled_compute_seconds": compute,
                "modelled_message_seconds": per_alpha * alpha, "modelled_control_seconds": 0.0}
    base = row(1.0, 1.0, 0.01)
    for r, kind, alpha in ((row(1.0, 2.0, 0.0), "at", 100.0),  # 1 s more compute, 0.01 s/us less
                           (row(0.5, 1.5, 0.01), "always", 0.0),  # half the MSE: wins throughout
                           (row(1.0, 1.5, 0.02), "never", None),
                           (row(2.0, 1.0, 0.0), "at", 100.0)):  # 2 x MSE: 2 s against 1 + 0.01 a
        got = extrapolated_break_even(base, r)
        if got[0] != kind or (alpha is not None and abs(got[1] - alpha) > 1e-9):
            failed += 1
            print(f"FAIL: extrapolated_break_even = {got}, expected ({kind!r}, {alpha})")
    for bad in (([], []), ([1, 2], [1]), ([2, 1], [1, 1])):
        try:
            break_even(*bad)
            failed += 1
            print(f"FAIL: break_even{bad} did not raise")
        except ValueError:
            pass
    if failed:
        sys.exit(f"bench_break_even self-test: {failed} failure(s)")
    print(f"bench_break_even self-test: {len(cases) + 7} checks pass")

"""One option per item within a cap, least summed value: the multiple-choice knapsack behind
allocate_proxy_budgets.py (an item is a mesh, an option its proxy at one face budget, the cost
its triangles times its instances, the value what its proxy wastes).

Solved exactly by dynamic programming over the cost, rounded up to units of cap / resolution:
rounding up keeps every choice within the cap, and costs off by less than one unit per item are
the only ones it may miss."""
import math


def choose(items, cap, resolution=10000):
    """items: for each item, its options as (cost, value) pairs. Returns (choice, value, cost):
    choice[i] is the index of item i's option, value and cost their sums; None when even the
    cheapest options exceed cap. Ties go to the smaller cost, then to the earlier option."""
    if not items:
        return [], 0.0, 0
    unit = max(cap / resolution, 1e-300) if cap > 0 else 1.0
    slots = int(math.floor(cap / unit)) if cap > 0 else 0
    inf = math.inf
    best = [0.0] + [inf] * slots  # best[c]: least value of the items so far at rounded cost c
    back = []
    for options in items:
        units = [math.ceil(cost / unit) for cost, _ in options]
        nxt = [inf] * (slots + 1)
        came = [None] * (slots + 1)
        for c, v in enumerate(best):
            if v == inf:
                continue
            for k, (_, value) in enumerate(options):
                n = c + units[k]
                if n <= slots and v + value < nxt[n]:
                    nxt[n] = v + value
                    came[n] = (c, k)
        best = nxt
        back.append(came)
    reachable = [c for c in range(slots + 1) if best[c] < inf]
    if not reachable:
        return None
    c = min(reachable, key=lambda s: (best[s], s))
    value = best[c]
    choice = [0] * len(items)
    for i in range(len(items) - 1, -1, -1):
        c, choice[i] = back[i][c]
    cost = sum(items[i][k][0] for i, k in enumerate(choice))
    return choice, value, cost

"""Deterministic random numbers for the scene scripts: SplitMix64 of integer keys."""


def rand(*keys):
    """SplitMix64 of the keys, mapped to [0, 1)."""
    h = 0x9E3779B97F4A7C15
    for k in keys:
        h = (h ^ (k + 0x632BE59BD9B4E019)) & 0xFFFFFFFFFFFFFFFF
        h = (h * 0xBF58476D1CE4E5B9) & 0xFFFFFFFFFFFFFFFF
        h ^= h >> 31
        h = (h * 0x94D049BB133111EB) & 0xFFFFFFFFFFFFFFFF
        h ^= h >> 29
    return (h >> 11) / float(1 << 53)

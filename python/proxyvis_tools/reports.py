"""The programs' JSON reports (docs/proxy_reports.md) as a comparison sees them: the keys that are
measured times or name the files a run wrote, and a report without such keys, so that what is
left must be equal between two runs of the same mesh and options (the programs, the Python
module, the Blender add-on)."""

# Keys of proxy-gen's and proxy-check's reports that are measured times...
TIMING_KEYS = frozenset({"seconds", "exact_seconds", "seconds_proxy", "seconds_original",
                         "cost_ratio"})
# ...and those, with the times, that name or hash a file.
FILE_KEYS = TIMING_KEYS | {"path", "output", "output_sha256", "file"}


def without(report, keys):
    """REPORT without KEYS at its top level and in its nested dicts and lists."""
    if isinstance(report, dict):
        return {k: without(v, keys) for k, v in report.items() if k not in keys}
    if isinstance(report, list):
        return [without(v, keys) for v in report]
    return report

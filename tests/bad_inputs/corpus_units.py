"""Inputs for render-compare's work-unit cases (cases_units.cmake): plan folders that are not
render-compare plans (none, broken JSON, a plan of another program)."""
import json
import pathlib


def build(out: pathlib.Path, data: pathlib.Path) -> None:
    (out / "units_empty").mkdir(exist_ok=True)
    broken = out / "units_broken_json"
    broken.mkdir(exist_ok=True)
    (broken / "plan.json").write_text('{"units": 3, "run_unit": [')
    other = out / "units_other_plan"
    other.mkdir(exist_ok=True)
    # A plan submit.sh accepts, written by another program: no "render_compare" settings.
    (other / "plan.json").write_text(json.dumps({
        "version": 1, "units": 2, "run_unit": ["/bin/true", "{unit}"], "merge": ["/bin/true"]}))

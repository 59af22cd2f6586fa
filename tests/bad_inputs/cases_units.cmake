# render-compare's work units (--plan, --run-unit, --merge; docs/slurm.md) on folders that hold no
# render-compare plan, and a plan that cannot be made: exit 2, one error line naming the file,
# nothing written. Corpus: corpus_units.py (and corpus_render.py's small scene).
bad_input_test(units_merge_without_plan render-compare "--merge @CORPUS@/units_empty"
  REGEX "units_empty/plan\\.json" WATCH @CORPUS@/units_empty TIMEOUT 20)
bad_input_test(units_merge_broken_plan render-compare "--merge @CORPUS@/units_broken_json"
  REGEX "units_broken_json/plan\\.json: not a render-compare plan"
  INPUTS @CORPUS@/units_broken_json/plan.json WATCH @CORPUS@/units_broken_json TIMEOUT 20)
bad_input_test(units_run_unit_other_plan render-compare "--run-unit @CORPUS@/units_other_plan 0"
  REGEX "units_other_plan/plan\\.json: not a render-compare plan"
  INPUTS @CORPUS@/units_other_plan/plan.json WATCH @CORPUS@/units_other_plan TIMEOUT 20)
# The automatic reference is sized from the equal-time renders, unknown at planning time.
bad_input_test(units_plan_equal_time_without_reference_spp render-compare
  "@CORPUS@/render_scene.json --out @OUT@/report --plan @OUT@/plan --equal-time 0.1"
  REGEX "--plan with --equal-time needs --reference-spp" INPUTS @CORPUS@/render_scene.json
  OUTPUTS @OUT@/plan/plan.json TIMEOUT 20)

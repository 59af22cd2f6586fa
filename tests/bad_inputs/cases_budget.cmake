# Face budgets (docs/budgets.md): a budget no verified proxy can meet is exit code 1 with one
# line saying what was reached and why, and nothing written; before, the proxy was written far
# over budget with exit code 0.
bad_input_test(budget_outside_wrap_3_faces proxy-gen
  "@CORPUS@/budget_sphere_180.off --kind outside --max-faces 3 -o @OUT@/p.ply --json @OUT@/p.json"
  CODE 1 REGEX "budget_sphere_180.off: budget of 3 faces not met: the smallest verified outside proxy has 4 faces; a closed surface needs at least 4"
  INPUTS @CORPUS@/budget_sphere_180.off TIMEOUT 30)
bad_input_test(budget_inside_wrap_3_faces proxy-gen
  "@CORPUS@/budget_sphere_180.off --kind inside --max-faces 3 -o @OUT@/p.ply"
  CODE 1 REGEX "budget_sphere_180.off: budget of 3 faces not met: the smallest verified inside proxy has 4 faces"
  INPUTS @CORPUS@/budget_sphere_180.off TIMEOUT 30)
# An erosion of a surface with no inside fails at once: cases_guarantee.cmake (theta).

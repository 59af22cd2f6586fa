# render-compare as work units (--plan, --run-unit, --merge; docs/slurm.md): sharded and single
# runs bit-identical on cornell-bunny, units run shuffled on one thread, missing / corrupt /
# foreign units refused at the merge, a killed unit rerun by submit.sh --resume --local. The same
# script runs a dragon-plane study on a real local Slurm (tests/slurm, label slurm).
if(CMAKE_SCRIPT_MODE_FILE)
  return()
endif()
proxyvis_python_test(app.render_compare.units render_compare_units.py
  $<TARGET_FILE:render-compare> ${CMAKE_SOURCE_DIR} --local)
set_tests_properties(app.render_compare.units PROPERTIES TIMEOUT 600)

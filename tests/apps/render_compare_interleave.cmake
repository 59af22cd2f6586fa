# render-compare's interleaved timing end to end: --repeats runs the equal-time schedule again
# with new seeds, every row carries its runs and the efficiency's run-to-run spread, the report
# says how the timing was done, and --repeats is checked like every number.
#
# Included from tests/apps/CMakeLists.txt this registers the tests; in script mode
# support/run_app.cmake includes it (with RCI_DIR set) to check the `--json -` report.
if(CMAKE_SCRIPT_MODE_FILE)
  expect_only_json_on_stdout("{" "}" "")
  string(JSON rows GET "${json}" rows)
  string(JSON n LENGTH "${rows}")
  if(NOT n EQUAL 4)
    message(FATAL_ERROR "${n} rows, expected 4 (2 equal-spp, 2 equal-time)")
  endif()
  expect_json_value("meta" "${json}" interleaved meta timing equal_time)
  expect_json_value("meta" "${json}" 2 meta repeats)
  string(JSON notes GET "${json}" notes)
  if(NOT notes MATCHES "Timing: equal-time renders are interleaved")
    message(FATAL_ERROR "no note on the interleaved timing:\n${notes}")
  endif()
  foreach(i RANGE 3)
    string(JSON row GET "${rows}" ${i})
    expect_json_keys("row ${i}" "${row}" efficiency_min efficiency_max efficiency_stderr
      efficiency_per_seed seconds_per_seed cpu_seconds repeats)
    string(JSON table GET "${row}" table)
    string(JSON estimator GET "${row}" estimator)
    string(JSON row_repeats GET "${row}" repeats)
    string(JSON runs LENGTH "${row}" mse_per_seed)
    string(JSON timed_runs LENGTH "${row}" seconds_per_seed)
    string(JSON ratios LENGTH "${row}" efficiency_per_seed)
    string(JSON lo GET "${row}" efficiency_min)
    string(JSON hi GET "${row}" efficiency_max)
    string(JSON se GET "${row}" efficiency_stderr)
    # Equal-spp cells have 2 seeds; equal-time cells 2 seeds x 2 repeats.
    set(want_runs 2)
    set(want_repeats 1)
    if(table STREQUAL "equal-time")
      set(want_runs 4)
      set(want_repeats 2)
    endif()
    if(NOT runs EQUAL want_runs OR NOT timed_runs EQUAL want_runs OR NOT ratios EQUAL want_runs
       OR NOT row_repeats EQUAL want_repeats)
      message(FATAL_ERROR "${table} ${estimator}: ${runs} MSEs, ${timed_runs} times, ${ratios} "
        "ratios, repeats ${row_repeats}; expected ${want_runs} runs, repeats ${want_repeats}")
    endif()
    if(NOT lo GREATER 0 OR hi LESS lo OR se LESS 0)
      message(FATAL_ERROR "${table} ${estimator}: spread [${lo}, ${hi}], s.e. ${se}")
    endif()
    # Exact against its own runs: 1 in every run.
    if(estimator STREQUAL "exact" AND (NOT lo EQUAL 1 OR NOT hi EQUAL 1 OR NOT se EQUAL 0))
      message(FATAL_ERROR "${table} exact: spread [${lo}, ${hi}], s.e. ${se}; expected [1, 1], 0")
    endif()
    # Each equal-time run spent the budget on its own clock.
    if(table STREQUAL "equal-time")
      foreach(k RANGE 3)
        string(JSON t GET "${row}" seconds_per_seed ${k})
        if(t LESS 0.05)
          message(FATAL_ERROR "equal-time ${estimator} run ${k}: ${t} s, budget 0.05 s")
        endif()
      endforeach()
    endif()
  endforeach()
  file(READ ${RCI_DIR}/report.md md)
  if(NOT md MATCHES "\\| exact \\| [0-9.]+ \\| [0-9.]+ \\| [^|]+ \\| [^|]+ \\| 1\\.00× \\[1\\.00–1\\.00, s\\.e\\. 0\\.00\\] \\|")
    message(FATAL_ERROR "report.md does not give the spread beside the efficiency:\n${md}")
  endif()
  return()
endif()

proxyvis_app_test_dir(rci_dir render_compare_interleave)
set(rci_common
  "${PROXYVIS_SCENES_DIR}/cornell-bunny.json --width 8 --height 8 --spp 1 --reference-spp 32")
proxyvis_app_test(app.render_compare.repeats_spread render-compare 0
  "${rci_common} --out ${rci_dir}/spread --equal-time 0.05 --seeds 2 --repeats 2 --estimators roulette,exact --quiet --json -"
  CLEAN ${rci_dir}/spread FILES ${rci_dir}/spread/report.html TIMEOUT 120
  CHECKS ${CMAKE_CURRENT_LIST_FILE} DEFS -DRCI_DIR=${rci_dir}/spread)
proxyvis_app_test(app.render_compare.repeats_out_of_range render-compare 2
  "${rci_common} --out ${rci_dir}/bad --repeats 0" REGEX "--repeats"
  NO_FILES ${rci_dir}/bad/report.json)
proxyvis_app_test(app.render_compare.repeats_without_equal_time render-compare 2
  "${rci_common} --out ${rci_dir}/bad --equal-time 0 --repeats 2"
  REGEX "render-compare: error: --repeats has nothing to repeat"
  NO_FILES ${rci_dir}/bad/report.json)

# The clearance of outside/inside proxies and the double reading of text meshes: a synthetic box
# whose dent rounds to opposite sides of a tight proxy's top in float and in double.
proxyvis_add_test(proxy_clearance_tests
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/clearance_test.cpp
  LIBS pv_proxy_pipeline pv_proxy_check pv_mesh)

# Every written class against the independent double-precision check: the bundled closed meshes
# and the hard set, outside and inside (default methods), at 2 % of their faces and at 200 faces (the hard set's own cases cover its meshes at 2 % and without a budget
# with every method). hard_set_case.py also checks the report's clearance and separation and
# proxy-check's verdict in both readings. CGAL-heavy: left out under the sanitizers, like the hard
# set.
find_package(Python3 REQUIRED COMPONENTS Interpreter)
# The open meshes of the hard set have no inside: outside only.
foreach(mesh bunny.off spot_triangulated.obj dragon.drc hard/3holes.off hard/fandisk.off hard/cow.off
    hard/truck.obj hard/camelhead.off hard/beetle.off)
  get_filename_component(stem ${mesh} NAME_WE)
  set(kinds outside inside)
  if(stem MATCHES "^(truck|camelhead|beetle)$")
    set(kinds outside)
  endif()
  foreach(kind ${kinds})
    foreach(budget 2pct 200)
      if(budget STREQUAL "2pct")
        if(mesh MATCHES "^hard/")
          continue()  # the hard set runs these
        endif()
        set(budget_args --ratio 0.02)
      else()
        set(budget_args --max-faces 200)
      endif()
      set(name proxy_gen_clearance.${stem}.${kind}.${budget})
      add_test(NAME ${name}
        COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/hard_set_case.py
          --bin $<TARGET_FILE_DIR:proxy-gen> --mesh ${PROXYVIS_DATA_DIR}/${mesh} --kind ${kind}
          --method wrap ${budget_args} --independent $<TARGET_FILE:independent_double_check>)
      set_tests_properties(${name} PROPERTIES LABELS "slow;not_sanitized" TIMEOUT 900
        FAIL_REGULAR_EXPRESSION "FAIL:" PASS_REGULAR_EXPRESSION "OK:")
    endforeach()
  endforeach()
endforeach()

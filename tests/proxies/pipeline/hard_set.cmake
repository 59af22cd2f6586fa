# The hard set (data/hard: meshes that break naive generators) through every proxy-gen kind and
# method, without a budget and at 2 % of the input faces. Each case runs proxy-gen as a user
# would and checks what it wrote with the other programs (hard_set_case.py): the written class
# holds against the input file, the budget is met or the run fails with one line and no output,
# nothing crashes. Refusals (exit 2) are accepted only where a case names the reason.
find_package(Python3 REQUIRED COMPONENTS Interpreter)

set(hard_dir ${CMAKE_SOURCE_DIR}/data/hard)
# An open input has no interior: an inside proxy is refused unless its holes are filled.
set(no_interior "boundary edges|non-manifold|no interior|has no inside")
set(closed_meshes 3holes.off fandisk.off cow.off)
set(open_meshes truck.obj camelhead.off beetle.off)
set(methods outside:wrap outside:hull outside:convex-parts inside:wrap inside:erode general:qem general:cgal-sms
  general:meshopt)

# hard_case(MESH KIND METHOD BUDGET_NAME RATIO [extra args for hard_set_case.py...])
function(hard_case mesh kind method budget_name ratio)
  get_filename_component(stem ${mesh} NAME_WE)
  set(name proxy_gen_hard.${stem}.${kind}.${method}.${budget_name})
  add_test(NAME ${name}
    COMMAND ${Python3_EXECUTABLE} ${CMAKE_CURRENT_LIST_DIR}/hard_set_case.py
      --bin $<TARGET_FILE_DIR:proxy-gen> --mesh ${hard_dir}/${mesh} --kind ${kind}
      --method ${method} --ratio ${ratio}
      --independent $<TARGET_FILE:independent_double_check> ${ARGN})
  # Under the sanitizers CGAL runs 5-10x slower: there only the two smallest meshes without a
  # budget (the whole matrix would take most of CI's time).
  set(labels hard_set slow)
  if(NOT (budget_name STREQUAL "none" AND stem MATCHES "^(cow|truck)$"))
    list(APPEND labels not_sanitized)
  endif()
  set_tests_properties(${name} PROPERTIES LABELS "${labels}" TIMEOUT 900
    FAIL_REGULAR_EXPRESSION "FAIL:" PASS_REGULAR_EXPRESSION "OK:")
endfunction()

foreach(mesh ${closed_meshes} ${open_meshes})
  list(FIND open_meshes ${mesh} is_open)
  foreach(km ${methods})
    string(REPLACE ":" ";" km ${km})
    list(GET km 0 kind)
    list(GET km 1 method)
    set(extra "")
    if(kind STREQUAL "inside" AND NOT is_open EQUAL -1)
      set(extra --allow-refusal "${no_interior}")
    endif()
    hard_case(${mesh} ${kind} ${method} none 0 ${extra})
    hard_case(${mesh} ${kind} ${method} 2pct 0.02 ${extra})
    if(kind STREQUAL "inside" AND NOT is_open EQUAL -1)
      # Filled holes: whatever is written must still hold for the input with its holes.
      hard_case(${mesh} ${kind} ${method} fill_holes 0 --fill-holes
        --allow-refusal "${no_interior}|could not all be triangulated")
    endif()
  endforeach()
endforeach()

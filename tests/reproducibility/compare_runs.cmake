# SPDX-License-Identifier: Zlib
# Runs btfracture-run twice on one scene and requires byte-identical results: statistics.csv
# without its wall-clock columns, fragments.csv and every OBJ frame. The first run must break
# something, so that the comparison covers fracture and not just rigid-body motion.
#   RUNNER  the runner executable        SCENE  scene file        OUT  scratch folder
#   ARGS    common arguments, separated by '|'
#   ARGS_A / ARGS_B   arguments of run A / run B only, separated by '|' (optional)
#   ENV_B   NAME=value set in run B's environment only (optional)
string(REPLACE "|" ";" common "${ARGS}")
string(REPLACE "|" ";" only_a "${ARGS_A}")
string(REPLACE "|" ";" only_b "${ARGS_B}")
set(env_b "")
if(DEFINED ENV_B AND NOT ENV_B STREQUAL "")
  set(env_b ${CMAKE_COMMAND} -E env "${ENV_B}")
endif()

function(simulate name launcher extra)
  file(REMOVE_RECURSE "${OUT}/${name}")
  execute_process(COMMAND ${launcher} "${RUNNER}" "${SCENE}" --out "${OUT}/${name}" --quiet ${common} ${extra}
                  RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "run ${name} failed (${code}):\n${out}\n${err}")
  endif()
endfunction()
simulate(a "" "${only_a}")
simulate(b "${env_b}" "${only_b}")

# statistics.csv without fracture_wall_s and swap_wall_s (columns 12 and 13, 0-based).
function(read_statistics path out_var)
  file(STRINGS "${path}" lines)
  set(kept "")
  foreach(line IN LISTS lines)
    string(REPLACE "," ";" fields "${line}")
    list(REMOVE_AT fields 12 13)
    list(APPEND kept "${fields}")
  endforeach()
  set(${out_var} "${kept}" PARENT_SCOPE)
endfunction()
read_statistics("${OUT}/a/statistics.csv" stats_a)
read_statistics("${OUT}/b/statistics.csv" stats_b)
file(STRINGS "${OUT}/a/statistics.csv" rows)
list(LENGTH rows row_count)
if(row_count LESS 2)
  message(FATAL_ERROR "run a broke nothing: the comparison would not cover fracture")
endif()
if(NOT stats_a STREQUAL stats_b)
  message(FATAL_ERROR "statistics.csv differs between the runs:\nA: ${stats_a}\nB: ${stats_b}")
endif()

file(GLOB frames RELATIVE "${OUT}/a" "${OUT}/a/frame_*.obj" "${OUT}/a/fragments.csv")
list(LENGTH frames frame_count)
if(frame_count EQUAL 0)
  message(FATAL_ERROR "run a wrote no OBJ frames")
endif()
foreach(frame IN LISTS frames)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${OUT}/a/${frame}" "${OUT}/b/${frame}"
                  RESULT_VARIABLE differ)
  if(NOT differ EQUAL 0)
    message(FATAL_ERROR "${frame} differs between the runs")
  endif()
endforeach()
math(EXPR events "${row_count} - 1")
message(STATUS "identical: ${events} fracture events, ${frame_count} files compared")

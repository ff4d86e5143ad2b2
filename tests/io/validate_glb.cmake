# SPDX-License-Identifier: Zlib
# Runs the runner on a scene (short) and validates its scene.glb with the Khronos glTF-Validator
# (tools/gltf-validator/validate.js): zero errors required. Also requires meshes/ and motion.csv
# with at least MIN_BODIES bodies (fragments included).
#   RUNNER  executable    NODE  node executable    VALIDATOR  validate.js
#   SCENE   scene file    OUT   output folder      ARGS  extra runner arguments, '|'-separated
#   MIN_BODIES  (optional) least number of bodies in motion.csv
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${RUNNER}" "${SCENE}" --out "${OUT}" --outputs motion,gltf --quiet ${args}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "runner failed (${code}):\n${out}\n${err}")
endif()
execute_process(COMMAND "${NODE}" "${VALIDATOR}" "${OUT}/scene.glb" RESULT_VARIABLE code OUTPUT_VARIABLE report
                ERROR_VARIABLE report_err)
message(STATUS "${report}${report_err}")
if(NOT code EQUAL 0)
  message(FATAL_ERROR "glTF-Validator reports errors in ${OUT}/scene.glb")
endif()
if(NOT report MATCHES ": 0 errors, ")
  message(FATAL_ERROR "no validator report for ${OUT}/scene.glb")
endif()
file(STRINGS "${OUT}/motion.csv" rows)
set(names "")
foreach(row IN LISTS rows)
  string(REGEX MATCH "^[0-9]+,[^,]*,([^,]*)," match "${row}")
  if(match)
    list(APPEND names "${CMAKE_MATCH_1}")
  endif()
endforeach()
list(REMOVE_DUPLICATES names)
list(LENGTH names bodies)
file(GLOB meshes "${OUT}/meshes/*.obj")
list(LENGTH meshes mesh_count)
if(NOT mesh_count EQUAL bodies)
  message(FATAL_ERROR "${mesh_count} meshes in ${OUT}/meshes for ${bodies} bodies in motion.csv")
endif()
if(DEFINED MIN_BODIES AND bodies LESS MIN_BODIES)
  message(FATAL_ERROR "${bodies} bodies in motion.csv, expected at least ${MIN_BODIES}")
endif()
message(STATUS "${bodies} bodies, each with its mesh; the validator reports no error")

# SPDX-License-Identifier: Zlib
# Re-generates the FractureRB example with its generator and checks that the committed files
# are exactly what it writes (the generator is deterministic).
#   GENERATOR  make_fracturerb_example   WORK_DIR  scratch folder   EXPECTED_DIR  demos/fracturerb
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
execute_process(COMMAND "${GENERATOR}" "${WORK_DIR}" RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT code EQUAL 0)
  message(FATAL_ERROR "generator failed (${code}):\n${out}${err}")
endif()
foreach(name brick_shot.bullet brick_shot.csv)
  execute_process(COMMAND ${CMAKE_COMMAND} -E compare_files "${WORK_DIR}/${name}" "${EXPECTED_DIR}/${name}"
                  RESULT_VARIABLE differs)
  if(differs)
    message(FATAL_ERROR "${EXPECTED_DIR}/${name} differs from what the generator writes now; "
                        "regenerate it: make_fracturerb_example ${EXPECTED_DIR}")
  endif()
endforeach()

# SPDX-License-Identifier: Zlib
# Installs btFracture into a fresh prefix and builds and runs tests/package/consumer against it.
#   MODE=installed : install the current build tree (BUILD_DIR)
#   MODE=rebuild   : configure, build and install a second tree of the whole project (SOURCE_DIR)
#                    in the other Bullet precision (library only: benchmarks and demos off,
#                    tests configured but not built)
#   MODE=stability : in that second tree, build and run the stability suite (hard cases
#                    in both Bullet precisions)
# Other inputs: SOURCE_DIR, BUILD_DIR, WORK_DIR, GENERATOR, BUILD_TYPE, DOUBLE (ON/OFF: the
# precision to install and expect), NATIVE, SANITIZE, JOBS.
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    string(REPLACE ";" " " command "${ARGN}")
    message(FATAL_ERROR "failed (${code}): ${command}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

# The second tree persists in WORK_DIR, so a re-run only rebuilds what changed.
set(tree "${WORK_DIR}/project-build")
if(MODE STREQUAL "stability")
  run(${CMAKE_COMMAND} --build "${tree}" -j ${JOBS} --target test_stability)
  # The hard cases as that tree's CTest registered them, JOBS at a time. Left out in double
  # Bullet: CurvedFragmentBreaksAgain (the ball hits the bunny's piece differently and it does
  # not break again: an outcome, not a stability failure).
  get_filename_component(cmake_bin "${CMAKE_COMMAND}" DIRECTORY)
  run("${cmake_bin}/ctest" --test-dir "${tree}/tests/stability" -j ${JOBS} --output-on-failure --no-tests=error
      -E "^Stability\.CurvedFragmentBreaksAgain$")
  message(STATUS "${last_output}")
  return()
endif()

set(prefix "${WORK_DIR}/prefix")
file(REMOVE_RECURSE "${prefix}" "${WORK_DIR}/consumer-build")

set(sanitize_flags "")
if(SANITIZE)
  set(sanitize_flags "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=address,undefined")
endif()

if(MODE STREQUAL "rebuild")
  run(${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${tree}" -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
      -DBTFRACTURE_BULLET_DOUBLE=${DOUBLE} -DBTFRACTURE_NATIVE=${NATIVE} -DBTFRACTURE_SANITIZE=${SANITIZE}
      -DBTFRACTURE_BUILD_TESTS=ON -DBTFRACTURE_BUILD_BENCH=OFF -DBTFRACTURE_BUILD_DEMOS=OFF)
  run(${CMAKE_COMMAND} --build "${tree}" -j ${JOBS} --target btFracture)
  run(${CMAKE_COMMAND} --install "${tree}" --prefix "${prefix}")
else()
  run(${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
endif()

run(${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/package/consumer" -B "${WORK_DIR}/consumer-build" -G "${GENERATOR}"
    -DCMAKE_BUILD_TYPE=${BUILD_TYPE} "-DCMAKE_PREFIX_PATH=${prefix}" -DEXPECT_BULLET_DOUBLE=${DOUBLE} ${sanitize_flags})
run(${CMAKE_COMMAND} --build "${WORK_DIR}/consumer-build")
run("${WORK_DIR}/consumer-build/app")
message(STATUS "${last_output}")

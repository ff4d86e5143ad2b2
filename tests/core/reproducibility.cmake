# SPDX-License-Identifier: Zlib
# Same results on CPUs with and without FMA: the brick scene through its first fracture event,
# run with glibc's default and its SSE2 libm variants (same_results_without_fma.cmake).
if(TARGET btfracture-run)
  add_test(NAME reproducibility.portable_math_env
           COMMAND ${CMAKE_COMMAND} -DRUNNER=$<TARGET_FILE:btfracture-run>
                   -DSCENE=${PROJECT_SOURCE_DIR}/demos/scenes/brick.json -DSTEPS=20
                   -DOUT=${CMAKE_CURRENT_BINARY_DIR}/portable_math_env
                   -P ${CMAKE_CURRENT_SOURCE_DIR}/same_results_without_fma.cmake)
  btfracture_timeout(timeout 180)
  set_tests_properties(reproducibility.portable_math_env PROPERTIES LABELS core TIMEOUT ${timeout})
endif()

# SPDX-License-Identifier: Zlib
# core.layering_rejects: cmake/CheckLayering.cmake must fail on tests/core/layering, a tree with
# one include against the module graph of each kind, and name every one of them.
#   cmake -DCHECKER=<CheckLayering.cmake> -DFIXTURE=<tests/core/layering> -P check_layering_rejects.cmake
execute_process(COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${FIXTURE} -P ${CHECKER}
                RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(code EQUAL 0)
  message(FATAL_ERROR "the layering check passed a tree with forbidden includes:\n${out}${err}")
endif()
set(expected
  "bem/UsesBullet.h: includes <btBulletDynamicsCommon.h>: bem must not use Bullet"
  "core/UsesOpenVdb.cpp: includes <openvdb/openvdb.h>: core must not use OpenVDB"
  "geometry/UsesFracture.h: includes <btFracture/fracture/Crack.h>: geometry may include only geometry, core"
  "geometry/VdbInHeader.h: includes <openvdb/openvdb.h>: OpenVDB only in .cpp files and geometry/internal/"
  "fracture/UsesInternal.cpp: includes <btFracture/geometry/internal/Grids.h>: internal to geometry"
  "core/Public.h: is public and includes <btFracture/core/Private.h>, which is not"
  "io/Quoted.cpp: includes \"Quoted.h\"")
foreach(line IN LISTS expected)
  string(FIND "${err}" "${line}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the layering check did not report '${line}':\n${err}")
  endif()
endforeach()
string(REGEX MATCHALL "btFracture/[^ \n]+\\.(h|cpp): (includes|is public)" reported "${err}")
list(LENGTH reported count)
list(LENGTH expected wanted)
if(NOT count EQUAL wanted)
  message(FATAL_ERROR "expected ${wanted} reports, got ${count} (io may use nlohmann-json and libpng):\n${err}")
endif()
message(STATUS "the layering check rejects all ${wanted} forbidden includes")

# SPDX-License-Identifier: Zlib
# Strict warnings for btFracture's own targets only; dependencies come in as SYSTEM headers.
# The fuzz build (clang) reports warnings without failing: the project's -Werror gate is GCC's.
function(btfracture_strict_warnings target)
  if(BTFRACTURE_FUZZ)
    target_compile_options(${target} PRIVATE -Wall -Wextra)
  else()
    target_compile_options(${target} PRIVATE -Wall -Wextra -Werror)
  endif()
  # GCC 12 reports false "may be used uninitialized" inside avx512fintrin.h when Eigen is
  # inlined with -march=native on AVX-512 machines (GCC bug 105593); keep it a warning. With the
  # sanitizers the same bug shows as "is used uninitialized". On AVX2-only machines (AMD EPYC)
  # the same inlining gives a false "array subscript is partly outside array bounds" in
  # avxintrin.h for a Vector4d comma-initialised from a Vector3d (seen in MeshDecimation.cpp): also a warning.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    target_compile_options(${target} PRIVATE -Wno-error=maybe-uninitialized -Wno-error=array-bounds)
    if(BTFRACTURE_SANITIZE)
      target_compile_options(${target} PRIVATE -Wno-error=uninitialized)
    endif()
  endif()
endfunction()

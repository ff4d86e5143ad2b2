# Strict warnings for btFracture's own targets only; dependencies come in as SYSTEM headers.
function(btfracture_strict_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Werror)
endfunction()

# SPDX-License-Identifier: Zlib
# BTFRACTURE_CHART_PYTHON: the Python 3 that draws the charts (scripts/charts/*.py, matplotlib):
# the first of /usr/bin/python3 (Debian's python3-matplotlib is on its path, not on that of a
# pyenv or venv python3 earlier on PATH) and python3 that imports matplotlib; empty when none
# does, and the runner and make bench-accuracy then write their CSVs without charts.
if(NOT DEFINED BTFRACTURE_CHART_PYTHON)
  set(_chart_python "")
  foreach(_candidate /usr/bin/python3 python3)
    execute_process(COMMAND ${_candidate} -c "import matplotlib" RESULT_VARIABLE _code OUTPUT_QUIET ERROR_QUIET)
    if(_code EQUAL 0)
      set(_chart_python "${_candidate}")
      break()
    endif()
  endforeach()
  set(BTFRACTURE_CHART_PYTHON "${_chart_python}" CACHE STRING "Python 3 with matplotlib for the charts; empty: none")
  if(NOT BTFRACTURE_CHART_PYTHON)
    message(STATUS "btFracture: no Python 3 with matplotlib (python3-matplotlib): runs write no charts")
  endif()
endif()

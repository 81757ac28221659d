# Script mode: scripts/study.py's value tests (tests/cli/study_py_test.py: the Pareto selection
# and FLIP of known image pairs), then study.py on the quick study's folder (FLIP, Pareto fronts,
# plots, tables). It needs the venv scripts/python_env.sh creates (flip-evaluator, matplotlib,
# numpy, from the network; scripts/setup.sh debug and scripts/study.sh run it). Without it the
# test prints SKIP and ctest reports it skipped, unless skips are forbidden (CI=true or
# GLINT_FORBID_SKIPS=1): then it fails.
include("${CMAKE_CURRENT_LIST_DIR}/python_env_check.cmake")
require_python(flip_evaluator matplotlib numpy)
execute_process(COMMAND "${PYTHON}" "${VALUE_TESTS}" -v RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "study.py's value tests failed (exit ${status})")
endif()
execute_process(COMMAND "${PYTHON}" "${SCRIPT}" "${OUT}" RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "study.py exited ${status}")
endif()
foreach(file IN ITEMS study.csv study.md reflections.png shadows.png scaling_resolution.png scaling_fraction.png)
  if(NOT EXISTS "${OUT}/${file}")
    message(FATAL_ERROR "study.py did not write ${file}")
  endif()
endforeach()
file(READ "${OUT}/study.csv" csv)
if(NOT csv MATCHES "flip" OR NOT csv MATCHES "pareto")
  message(FATAL_ERROR "study.csv lacks the flip and pareto columns")
endif()

# For the script-mode tests of the Python scripts (scripts/study.py, scripts/run_flip.py): they
# need the venv scripts/python_env.sh creates (flip-evaluator, matplotlib, numpy, from the
# network; scripts/setup.sh debug and scripts/study.sh run it). require_python(module...) returns
# from the calling script, after printing SKIP, when ${PYTHON} is missing or lacks a module;
# where skips are forbidden (CI=true or GLINT_FORBID_SKIPS=1) it fails instead.
function(cannot_run reason)
  if("$ENV{CI}" STREQUAL "true" OR ("$ENV{GLINT_FORBID_SKIPS}" AND NOT "$ENV{GLINT_FORBID_SKIPS}" STREQUAL "0"))
    message(FATAL_ERROR "cannot run, and skips are forbidden here: ${reason}")
  endif()
  message("SKIP: ${reason}")
endfunction()
macro(require_python)
  set(python_modules ${ARGN})
  list(JOIN python_modules ", " python_import)
  if(NOT EXISTS "${PYTHON}")
    cannot_run("no ${PYTHON}; scripts/python_env.sh creates it")
    return()
  endif()
  execute_process(COMMAND "${PYTHON}" -c "import ${python_import}" RESULT_VARIABLE python_status)
  if(NOT python_status EQUAL 0)
    cannot_run("${PYTHON} lacks one of ${python_import}; scripts/python_env.sh installs them")
    return()
  endif()
endmacro()

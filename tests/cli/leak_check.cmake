# Runs glint verbs with LeakSanitizer on (the sanitizer build; the test preset turns it off for
# the test binaries) and fails on any leak report or a non-zero exit.
#   -DGLINT=<glint> -DSUPPRESSIONS=<lsan.supp> -DSAMPLE=<sample sequence> -DSCENE=<scene.toml> -DOUT=<folder>
set(ENV{ASAN_OPTIONS} "detect_leaks=1:abort_on_error=0")
set(ENV{LSAN_OPTIONS} "suppressions=${SUPPRESSIONS}:print_suppressions=0")
file(REMOVE_RECURSE "${OUT}")
# One command per entry, its arguments separated by '|'.
set(verbs
  "devices"
  "settings"
  "info|${SAMPLE}"
  "simulate|${SCENE}|--size|24x16|--frame-count|2|--spp|1|--out|${OUT}/capture"
  "--validate|run|${SAMPLE}|--out|${OUT}/run"
  "dump|${SAMPLE}|--pass|all|--out|${OUT}/dump"
  "check|${SAMPLE}|--expected|${OUT}/dump"
  "bench|${SAMPLE}|--runs|2"
  "run|${OUT}/capture|--effects|hybrid|--out|${OUT}/hybrid")
foreach(entry IN LISTS verbs)
  string(REPLACE "|" ";" verb "${entry}")
  string(REPLACE "|" " " shown "${entry}")
  execute_process(COMMAND "${GLINT}" ${verb} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(err MATCHES "LeakSanitizer")
    message(FATAL_ERROR "glint ${shown}: LeakSanitizer report:\n${err}")
  endif()
  if(NOT code EQUAL 0)
    message(FATAL_ERROR "glint ${shown}: exit ${code}\n${err}")
  endif()
endforeach()

# check_layers_planted.cmake -- the layer check fails on a planted violation.
#
#   cmake -DKERNEL=<kernel dir> -DORDER=<README.md> -DALLOW=<allowed list> -DWORK=<scratch dir>
#         -DCHECK=<check_layers.cmake> -P check_layers_planted.cmake
#
# Copies kernel/ to WORK, adds one include that goes up (support/cpu_clock.h, the bottom
# layer, including pipeline/edf2d.h, near the top) and one that stays in its layer, and
# requires check_layers.cmake to fail on the copy, naming exactly the planted include;
# then requires it to pass on the unchanged copy (so the failure is the planted line's).
cmake_policy(VERSION 3.18)
file(REMOVE_RECURSE "${WORK}")
file(COPY "${KERNEL}/" DESTINATION "${WORK}/kernel")
set(victim "${WORK}/kernel/support/cpu_clock.h")
if(NOT EXISTS "${victim}")
  message(FATAL_ERROR "check_layers_planted: ${victim} is missing")
endif()
file(READ "${victim}" original)

macro(run_check out_result out_text)
  execute_process(COMMAND "${CMAKE_COMMAND}" -DKERNEL=${WORK}/kernel -DORDER=${ORDER} -DALLOW=${ALLOW}
                          -P "${CHECK}"
                  RESULT_VARIABLE ${out_result} OUTPUT_VARIABLE o ERROR_VARIABLE e)
  set(${out_text} "${o}${e}")
endmacro()

run_check(clean_result clean_text)
if(NOT clean_result EQUAL 0)
  message(FATAL_ERROR "check_layers_planted: the check fails on the unchanged copy:\n${clean_text}")
endif()

file(WRITE "${victim}" "${original}\n#include \"pipeline/edf2d.h\"\n#include \"support/progress.h\"\n")
run_check(bad_result bad_text)
file(REMOVE_RECURSE "${WORK}")
if(bad_result EQUAL 0)
  message(FATAL_ERROR "check_layers_planted: the check passed with an include going up:\n${bad_text}")
endif()
if(NOT bad_text MATCHES "support/cpu_clock.h -> pipeline/edf2d.h: goes up")
  message(FATAL_ERROR "check_layers_planted: the check failed without naming the planted include:\n${bad_text}")
endif()
if(bad_text MATCHES "support/progress.h")
  message(FATAL_ERROR "check_layers_planted: the check rejected an include inside one layer:\n${bad_text}")
endif()
string(REGEX MATCH "check_layers: [0-9]+ violation" count "${bad_text}")
if(NOT count STREQUAL "check_layers: 1 violation")
  message(FATAL_ERROR "check_layers_planted: expected exactly one violation, got:\n${bad_text}")
endif()
message(STATUS "check_layers_planted: the planted include was reported, and only it")

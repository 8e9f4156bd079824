# check_install.cmake -- installs the built grassfire into a fresh temporary prefix, then
# configures, builds and runs the consumer project against it (docs/library.md: "Using grassfire as
# a library"). Nothing is rebuilt: `cmake --install` copies what the build made.
# Run as: cmake -DBUILD_DIR=... -DCONSUMER=... -DCXX=... [-DLAUNCHER=...] -P check_install.cmake
set(tmp_root "$ENV{TMPDIR}")
if(NOT tmp_root)
  set(tmp_root /tmp)
endif()
execute_process(COMMAND mktemp -d "${tmp_root}/grassfire_install_XXXXXX" OUTPUT_VARIABLE work
                OUTPUT_STRIP_TRAILING_WHITESPACE RESULT_VARIABLE failed)
if(failed)
  message(FATAL_ERROR "cannot make a temporary folder in ${tmp_root}")
endif()

function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(code)
    file(REMOVE_RECURSE "${work}")
    message(FATAL_ERROR "${what} failed (${code}):\n${out}")
  endif()
  message(STATUS "${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

step("install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${work}/prefix")
foreach(f include/grassfire/pipeline/edf2d.h include/grassfire/grassfire_version.h bin/grassfire
        lib/cmake/grassfire/grassfireConfig.cmake lib/cmake/grassfire/grassfireConfigVersion.cmake)
  if(NOT EXISTS "${work}/prefix/${f}")
    file(REMOVE_RECURSE "${work}")
    message(FATAL_ERROR "the install has no ${f}")
  endif()
endforeach()
step("configure the consumer" ${CMAKE_COMMAND} -S "${CONSUMER}" -B "${work}/consumer" -DCMAKE_BUILD_TYPE=Release
     "-DCMAKE_PREFIX_PATH=${work}/prefix" "-DCMAKE_CXX_COMPILER=${CXX}" "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
step("build the consumer" ${CMAKE_COMMAND} --build "${work}/consumer")
step("run the consumer" "${work}/consumer/consumer")
message(STATUS "${step_output}")
step("run the installed program" "${work}/prefix/bin/grassfire" --version)
message(STATUS "${step_output}")
file(REMOVE_RECURSE "${work}")

# Shared by the install tests run with `cmake -P` (install_and_consume.cmake, debian_package.cmake).
# They expect WORK_DIR, SOURCE_DIR, GENERATOR, CXX_COMPILER, BUILD_TYPE, CXX_FLAGS,
# CXX_FLAGS_BUILD_TYPE and LAUNCHER to be defined.

# Runs a command; fails the test with its output unless it exits with `expected` (default 0).
# Its standard output is in `${out_var}`, its standard error in `${out_var}_stderr`.
function(run out_var)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "EXPECT;WORKING_DIRECTORY" "COMMAND")
  if(NOT DEFINED arg_EXPECT)
    set(arg_EXPECT 0)
  endif()
  if(NOT arg_WORKING_DIRECTORY)
    set(arg_WORKING_DIRECTORY "${WORK_DIR}")
  endif()
  execute_process(COMMAND ${arg_COMMAND} WORKING_DIRECTORY "${arg_WORKING_DIRECTORY}"
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status STREQUAL arg_EXPECT)
    message(FATAL_ERROR "exit ${status} (expected ${arg_EXPECT}): ${arg_COMMAND}\n${out}\n${err}")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${out_var}_stderr "${err}" PARENT_SCOPE)
endfunction()

# Builds examples/cpp_consumer with find_package against `prefix`, compiled as the libraries were
# (compiler, build type and its flags: an inline function compiled on both sides is kept once,
# from either; docs/install.md), runs it without TOUCHDOWN_DATA_DIR and puts its output (JSON) in
# `${out_var}`.
function(build_and_run_consumer prefix out_var)
  set(consumer_build "${WORK_DIR}/consumer")
  set(configure_args -S "${SOURCE_DIR}/examples/cpp_consumer" -B "${consumer_build}" -G "${GENERATOR}"
    "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
  if(BUILD_TYPE)
    string(TOUPPER "${BUILD_TYPE}" build_type)
    list(APPEND configure_args "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_CXX_FLAGS_${build_type}=${CXX_FLAGS_BUILD_TYPE}")
  endif()
  if(LAUNCHER)
    list(APPEND configure_args "-DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER}")
  endif()
  run(ignored COMMAND "${CMAKE_COMMAND}" ${configure_args})
  run(ignored COMMAND "${CMAKE_COMMAND}" --build "${consumer_build}")
  run(consumer COMMAND "${CMAKE_COMMAND}" -E env --unset=TOUCHDOWN_DATA_DIR "${consumer_build}/cpp_consumer")
  set(${out_var} "${consumer}" PARENT_SCOPE)
endfunction()

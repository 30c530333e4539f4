# cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... -DPYTHON=... [-DNINJA=...] -P quickstart.cmake
# The README's quick start on the build it made (tests/install/CMakeLists.txt): what
# tools/run_main.sh builds (target touchdown_quickstart) is everything `cmake --install` installs,
# the README's Python line runs as written from a directory laid out like the repository root, and
# `cmake --install` of the build into a fresh prefix completes (bin/, share/, lib/cmake/, the module).
cmake_minimum_required(VERSION 3.20)
foreach(var BUILD_DIR WORK_DIR SOURCE_DIR PYTHON)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "quickstart.cmake: -D${var}=... is missing")
  endif()
endforeach()
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# 1. The quick start's target builds every file the install copies (the files the install checks
#    first: touchdown_install_check.cmake). Ninja lists what a target depends on.
file(STRINGS "${BUILD_DIR}/touchdown_install_check.cmake" checks REGEX "^if\\(NOT EXISTS \"")
list(LENGTH checks installed_count)
if(installed_count LESS 19)  # 17 module libraries, the executable and the Python module
  message(FATAL_ERROR "the install check lists ${installed_count} built files, expected at least 19")
endif()
if(NINJA)
  # `-t query`: the target's own inputs (the executable, the module); `-t inputs`: theirs, recursively.
  set(inputs "")
  foreach(tool query inputs)
    execute_process(COMMAND "${NINJA}" -C "${BUILD_DIR}" -t ${tool} touchdown_quickstart
      OUTPUT_VARIABLE listed RESULT_VARIABLE status)
    if(NOT status EQUAL 0)
      message(FATAL_ERROR "ninja -t ${tool} touchdown_quickstart failed (${status})")
    endif()
    string(REGEX REPLACE "\n *" ";" listed "${listed}")
    list(APPEND inputs ${listed})
  endforeach()
  foreach(check ${checks})
    string(REGEX REPLACE "^if\\(NOT EXISTS \"([^\"]*)\"\\).*" "\\1" file "${check}")
    file(RELATIVE_PATH relative "${BUILD_DIR}" "${file}")
    if(NOT relative IN_LIST inputs AND NOT file IN_LIST inputs)
      message(FATAL_ERROR "the quick start (tools/run_main.sh, target touchdown_quickstart) does not build "
        "${relative}, which `cmake --install` installs")
    endif()
  endforeach()
endif()

# 2. The README's Python line, as written, from a root whose build/ is this build (run by bash from a
#    script file, as tests/apps/readme_test.cpp runs the examples).
file(STRINGS "${SOURCE_DIR}/README.md" lines REGEX "^PYTHONPATH=build/python python3 ")
list(LENGTH lines count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "README.md: expected one line `PYTHONPATH=build/python python3 ...`, found ${count}")
endif()
file(READ "${SOURCE_DIR}/README.md" readme)  # the line itself unescaped (file(STRINGS) escapes its ';')
string(REGEX MATCH "\nPYTHONPATH=build/python python3 [^\n]*" line "${readme}")
string(STRIP "${line}" line)
set(root "${WORK_DIR}/root")
file(MAKE_DIRECTORY "${root}")
file(CREATE_LINK "${BUILD_DIR}" "${root}/build" SYMBOLIC)
file(CREATE_LINK "${SOURCE_DIR}/data" "${root}/data" SYMBOLIC)
file(WRITE "${WORK_DIR}/python_line.sh" "${line}\n")
execute_process(COMMAND bash "${WORK_DIR}/python_line.sh" WORKING_DIRECTORY "${root}"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(STRIP "${out}" out)
if(NOT status EQUAL 0 OR NOT out MATCHES "^0\\.0078")
  message(FATAL_ERROR "README's Python line: exit ${status}, printed '${out}' (expected 0.0078...)\n${err}")
endif()

# 3. The install of this build into a new prefix completes.
set(prefix "${WORK_DIR}/prefix")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status}):\n${err}")
endif()
file(GLOB config "${prefix}/lib*/cmake/touchdown/touchdownConfig.cmake")
file(GLOB_RECURSE module "${prefix}/lib/python3/dist-packages/touchdown/_touchdown*.so")
if(NOT EXISTS "${prefix}/bin/touchdown" OR NOT IS_DIRECTORY "${prefix}/share/touchdown/pads" OR NOT config
   OR NOT module)
  message(FATAL_ERROR "incomplete install in ${prefix}: bin/touchdown, share/touchdown/pads, "
    "lib/cmake/touchdown/touchdownConfig.cmake and the Python module are expected")
endif()
# The installed module imports from the prefix (its pure-Python part beside the compiled one).
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "PYTHONPATH=${prefix}/lib/python3/dist-packages"
  "${PYTHON}" -c "import touchdown, sys; sys.exit(0 if touchdown.__file__.startswith('${prefix}') else 1)"
  RESULT_VARIABLE status ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the installed Python module does not import from ${prefix}:\n${err}")
endif()
message(STATUS "quick start: Python line printed ${out}; install into ${prefix} complete")

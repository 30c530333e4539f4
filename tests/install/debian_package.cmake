# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -DCXX_COMPILER=... -DBUILD_TYPE=...
#       [-DCXX_FLAGS=... -DCXX_FLAGS_BUILD_TYPE=... -DLAUNCHER=...] -DPYTHON=... -P debian_package.cmake
# The Debian package (cmake/TouchdownPackage.cmake) as apt would install it, without root: `cpack
# -G DEB` of BUILD_DIR, unpacked with `dpkg-deb -x` under WORK_DIR (its /usr is WORK_DIR/root/usr).
# The unpacked command line runs a drop from its own data, without $TOUCHDOWN_DATA_DIR; python3
# imports the unpacked module (PYTHONPATH is the dist-packages folder, which an installed package
# has on python3's path anyway) and finds the same data; examples/cpp_consumer builds against the
# unpacked CMake package (CMAKE_PREFIX_PATH, which /usr needs not). No LD_LIBRARY_PATH: the
# package has no shared library of its own (the module libraries are static), and the system's
# are where the Depends put them. Prints "debian_package: skipped" (CTest: skipped) without cpack
# or dpkg-deb.
cmake_minimum_required(VERSION 3.20)
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER BUILD_TYPE PYTHON)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "debian_package.cmake: -D${var}=... is missing")
  endif()
endforeach()
find_program(dpkg_deb dpkg-deb)
get_filename_component(cmake_bin "${CMAKE_COMMAND}" DIRECTORY)
find_program(cpack cpack HINTS "${cmake_bin}" NO_DEFAULT_PATH)
if(NOT cpack)
  find_program(cpack cpack)
endif()
if(NOT dpkg_deb OR NOT cpack)
  message("debian_package: skipped (needs cpack and dpkg-deb: apt-get install cmake dpkg)")
  return()
endif()

include("${CMAKE_CURRENT_LIST_DIR}/package_test_helpers.cmake")

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
# 1. The package, built as the README says (its scratch files under WORK_DIR, not the build's).
run(ignored COMMAND "${cpack}" -G DEB --config "${BUILD_DIR}/CPackConfig.cmake" -B "${WORK_DIR}/cpack"
  WORKING_DIRECTORY "${BUILD_DIR}")
file(GLOB debs "${WORK_DIR}/cpack/touchdown_*.deb")
list(LENGTH debs deb_count)
if(NOT deb_count EQUAL 1)
  message(FATAL_ERROR "expected one touchdown_*.deb in ${WORK_DIR}/cpack, found: ${debs}")
endif()
get_filename_component(deb_name "${debs}" NAME)
run(version COMMAND "${dpkg_deb}" -f "${debs}" Version)
run(arch COMMAND "${dpkg_deb}" -f "${debs}" Architecture)
string(STRIP "${version}" version)
string(STRIP "${arch}" arch)
if(NOT deb_name STREQUAL "touchdown_${version}_${arch}.deb")
  message(FATAL_ERROR "package file ${deb_name}, expected touchdown_${version}_${arch}.deb")
endif()
# Its Depends: the Python interpreter and gnuplot as declared, the shared libraries by dpkg-shlibdeps.
run(depends COMMAND "${dpkg_deb}" -f "${debs}" Depends)
foreach(needed "python3" "python3-numpy" "gnuplot-nox" "libyaml-cpp" "libsqlite3" "libstdc\\+\\+6")
  if(NOT depends MATCHES "(^|[ ,|])${needed}")
    message(FATAL_ERROR "Depends lacks ${needed}: ${depends}")
  endif()
endforeach()

# 2. Unpacked: everything under /usr, nothing of this build's or source tree's paths in its text.
set(root "${WORK_DIR}/root")
run(ignored COMMAND "${dpkg_deb}" -x "${debs}" "${root}")
set(usr "${root}/usr")
file(GLOB module "${usr}/lib/python3/dist-packages/touchdown/_touchdown*.so")
foreach(file bin/touchdown share/touchdown/pads/flat.yaml share/touchdown/scenarios/lander_case_B.yaml
    lib/cmake/touchdown/touchdownConfig.cmake lib/libtouchdown_rft.a include/rft/contact_wrench.h
    lib/python3/dist-packages/touchdown/__init__.py)
  if(NOT EXISTS "${usr}/${file}")
    message(FATAL_ERROR "not in the package: /usr/${file}")
  endif()
endforeach()
if(NOT module)
  message(FATAL_ERROR "not in the package: the compiled Python module")
endif()
file(GLOB_RECURSE package_files LIST_DIRECTORIES false "${root}/*")
foreach(file ${package_files})
  if(NOT file MATCHES "\\.(a|so)$" AND NOT file MATCHES "/bin/touchdown$")
    file(READ "${file}" text)
    string(FIND "${text}" "${BUILD_DIR}" in_build)
    string(FIND "${text}" "${SOURCE_DIR}/" in_source)
    if(NOT in_build EQUAL -1 OR NOT in_source EQUAL -1)
      message(FATAL_ERROR "${file} names the build's or the source tree's paths")
    endif()
  endif()
endforeach()

# 3. The unpacked command line: one drop on a pad only the package's data has, from WORK_DIR.
set(no_env "${CMAKE_COMMAND}" -E env --unset=TOUCHDOWN_DATA_DIR)
file(COPY_FILE "${usr}/share/touchdown/pads/flat.yaml" "${usr}/share/touchdown/pads/deb_only_flat.yaml")
run(cli_drop COMMAND ${no_env} "${usr}/bin/touchdown" drop --pad deb_only_flat --soil fjs1_lp --speed 1)
string(JSON peak GET "${cli_drop}" peak_force_N)
if(NOT peak GREATER 100)
  message(FATAL_ERROR "touchdown drop from the package: ${cli_drop}")
endif()
run(cli_version COMMAND "${usr}/bin/touchdown" --version)

# 4. The unpacked Python module: its version, its data (the package's), the same drop.
run(py COMMAND ${no_env} "PYTHONPATH=${usr}/lib/python3/dist-packages" PYTHONDONTWRITEBYTECODE=1 "${PYTHON}" -c
  "import json, touchdown; print(json.dumps({'version': touchdown.__version__, 'data': touchdown.data_dir(), \
'file': touchdown.__file__, 'drop': touchdown.drop(pad='deb_only_flat', soil='fjs1_lp', speed=1.0)}))")
string(JSON py_version GET "${py}" version)
string(JSON py_data GET "${py}" data)
string(JSON py_file GET "${py}" file)
string(JSON py_peak GET "${py}" drop peak_force_N)
file(REAL_PATH "${py_data}" py_data)
file(REAL_PATH "${usr}/share/touchdown" package_data)
if(NOT cli_version STREQUAL "touchdown ${py_version}\n" OR NOT py_data STREQUAL package_data
    OR NOT py_file MATCHES "^${usr}/" OR NOT py_peak EQUAL peak)
  message(FATAL_ERROR "import touchdown from the package: ${py}\n(touchdown --version: ${cli_version}, "
    "data expected ${package_data}, drop peak ${peak} N)")
endif()

# 5. A program of one's own on the unpacked CMake package (package_test_helpers.cmake).
build_and_run_consumer("${usr}" consumer)
string(JSON consumer_peak GET "${consumer}" drop peak_force_N)
if(NOT consumer_peak GREATER 100)
  message(FATAL_ERROR "cpp_consumer on the package: ${consumer}")
endif()
file(SIZE "${debs}" deb_bytes)
math(EXPR deb_kib "${deb_bytes} / 1024")
message(STATUS "${deb_name}: ${deb_kib} KiB; drop peak ${peak} N from the command line, the module and "
  "(${consumer_peak} N, default pad) a program built on its CMake package")

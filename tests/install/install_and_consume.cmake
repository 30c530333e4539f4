# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DGENERATOR=... -DCXX_COMPILER=...
#       -DBUILD_TYPE=... [-DCXX_FLAGS=... -DCXX_FLAGS_BUILD_TYPE=... -DLAUNCHER=...] -P install_and_consume.cmake
# Checks the installed package (tests/install/CMakeLists.txt): installs BUILD_DIR into WORK_DIR,
# moves the prefix (nothing in it may name where it was installed), checks that CGAL stays
# inside footpad_geom, builds examples/cpp_consumer against it, and compares the consumer's force
# and drop with the installed command line's, run from WORK_DIR without $TOUCHDOWN_DATA_DIR.
cmake_minimum_required(VERSION 3.20)
foreach(var BUILD_DIR SOURCE_DIR WORK_DIR GENERATOR CXX_COMPILER BUILD_TYPE)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "install_and_consume.cmake: -D${var}=... is missing")
  endif()
endforeach()

include("${CMAKE_CURRENT_LIST_DIR}/package_test_helpers.cmake")

# This test's own scratch folder, inside the build tree.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(stage "${WORK_DIR}/stage")
set(prefix "${WORK_DIR}/moved prefix")  # a space in the path, as users' paths have
run(ignored COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${stage}")
file(RENAME "${stage}" "${prefix}")

# What is installed: the 17 module libraries, the command line, the data, the package files.
foreach(module rft footpad_geom integ pad multibody util formats catalog model drop dataset scenario sweep gap
    stability validation targets)
  file(GLOB library "${prefix}/lib*/libtouchdown_${module}.*")
  if(NOT library)
    message(FATAL_ERROR "module library touchdown_${module} not installed under ${prefix}/lib")
  endif()
endforeach()
foreach(file bin/touchdown share/touchdown/pads/flat.yaml share/touchdown/soils/fjs1_lp.yaml
    include/rft/contact_wrench.h include/drop_tests/drop/pad_drop.h include/lander/pad/pad_pose.h)
  if(NOT EXISTS "${prefix}/${file}")
    message(FATAL_ERROR "not installed: ${file}")
  endif()
endforeach()
file(GLOB_RECURSE config_files "${prefix}/lib*/cmake/touchdown/*.cmake")
list(LENGTH config_files config_count)
if(config_count LESS 3)
  message(FATAL_ERROR "package files missing: ${config_files}")
endif()

# CGAL stays private to footpad_geom's sources: no installed header includes it and the package
# neither finds nor links it (its number types, GMP and MPFR, are linked by file name).
file(GLOB_RECURSE headers "${prefix}/include/*.h")
foreach(header ${headers})
  file(STRINGS "${header}" cgal_includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]CGAL/")
  if(cgal_includes)
    message(FATAL_ERROR "installed header includes CGAL: ${header}: ${cgal_includes}")
  endif()
endforeach()
foreach(file ${config_files})
  file(STRINGS "${file}" cgal_lines REGEX "CGAL[:_ ]")
  foreach(line ${cgal_lines})
    if(NOT line MATCHES "^#")
      message(FATAL_ERROR "the installed package names CGAL: ${file}: ${line}")
    endif()
  endforeach()
endforeach()

# The installed command line, from another directory, without $TOUCHDOWN_DATA_DIR: it finds its
# data beside itself. A pad only the installed copy has tells that copy from the source tree's.
set(touchdown "${prefix}/bin/touchdown")
set(no_env "${CMAKE_COMMAND}" -E env --unset=TOUCHDOWN_DATA_DIR)
file(COPY_FILE "${prefix}/share/touchdown/pads/flat.yaml" "${prefix}/share/touchdown/pads/installed_only_flat.yaml")
run(cli_force COMMAND ${no_env} "${touchdown}" force --pad installed_only_flat --soil fjs1_lp --depth 0.02)
run(cli_drop COMMAND ${no_env} "${touchdown}" drop --pad flat --soil fjs1_lp --speed 1)
# $TOUCHDOWN_DATA_DIR still comes first: a folder without a pads/ shelf is named (exit 2, one line).
file(MAKE_DIRECTORY "${WORK_DIR}/empty_data")
run(ignored EXPECT 2 COMMAND "${CMAKE_COMMAND}" -E env "TOUCHDOWN_DATA_DIR=${WORK_DIR}/empty_data"
  "${touchdown}" drop --pad flat --soil fjs1_lp --speed 1)
if(NOT ignored_stderr MATCHES "empty_data/pads: pads: no such data directory")
  message(FATAL_ERROR "with TOUCHDOWN_DATA_DIR set, expected the empty folder named, got: ${ignored_stderr}")
endif()

# A program of the user's own, built against the moved prefix by find_package.
build_and_run_consumer("${prefix}" consumer)

# Its numbers are the command line's, bit for bit (the same library code; JSON numbers are
# compared as the doubles they parse to).
string(JSON consumer_fz GET "${consumer}" force force_N 2)
string(JSON cli_fz GET "${cli_force}" force_N 2)
string(JSON consumer_area GET "${consumer}" force submerged_area_m2)
string(JSON cli_area GET "${cli_force}" submerged_area_m2)
if(NOT consumer_fz STREQUAL cli_fz OR NOT consumer_area STREQUAL cli_area OR NOT cli_fz GREATER 500)
  message(FATAL_ERROR "force: consumer ${consumer_fz} N on ${consumer_area} m^2, "
    "touchdown force ${cli_fz} N on ${cli_area} m^2")
endif()
string(JSON consumer_drop GET "${consumer}" drop)
string(JSON same EQUAL "${consumer_drop}" "${cli_drop}")
string(JSON peak GET "${cli_drop}" peak_force_N)
if(NOT same OR NOT peak GREATER 100)
  message(FATAL_ERROR "drop: the consumer's summary\n${consumer_drop}\ndiffers from touchdown drop's\n${cli_drop}")
endif()
message(STATUS "installed package: force ${cli_fz} N, drop peak force ${peak} N, as the command line's")

# `cpack -G DEB` in the build directory (README, docs/install.md): touchdown_<version>_<arch>.deb
# holding what `cmake --install` installs, under /usr: /usr/bin/touchdown, its data in
# /usr/share/touchdown (found beside the executable, drop_tests/catalog/catalog.cpp: DataDirectory),
# the Python package in /usr/lib/python3/dist-packages/touchdown (finding the same data beside
# itself, apps/python/touchdown/__init__.py), and the module libraries with their headers and CMake
# package (/usr/lib/cmake/touchdown). Every path in it is relative to the prefix, so the tree the
# package unpacks to works wherever it is (tests/install/debian_package.cmake runs it unpacked
# under a temporary directory).
#
# Build the package from a portable build (TOUCHDOWN_NATIVE OFF, the default) to install it on
# other machines: a native build's code, and the -march=native its CMake package asks of
# programs linking it, run only on CPUs like the building one.
set(CPACK_PACKAGE_NAME touchdown)
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "lander footpads hitting granular regolith, simulated with granular RFT")
set(CPACK_PACKAGE_DESCRIPTION "Footpad trade studies, drop-test sweeps, landing-stability studies of a \
four-legged lander and the comparison of simulated with measured drops, with resistive force theory \
(the touchdown command, its Python module and its C++ libraries).")
if(TOUCHDOWN_NATIVE)  # said where apt shows it (apt show touchdown), since nothing else tells
  string(APPEND CPACK_PACKAGE_DESCRIPTION " Built with -march=native (TOUCHDOWN_NATIVE): it runs only on \
CPUs like the one that built it; tools/build.sh --package makes the portable package.")
endif()
set(CPACK_PACKAGE_CONTACT "touchdown maintainers")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # touchdown_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
# The shared libraries the executable and the Python module load (yaml-cpp, SUNDIALS, SQLite,
# Ceres, GMP, MPFR, MPI when built with it) become Depends through dpkg-shlibdeps, looked for when
# cpack runs (Debian's dpkg-dev: `tools/install_deps.sh package`); without it cpack says so and
# the package lists only the Depends below.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# What no library link says: the Python module's interpreter and the numpy its trace arrays are;
# gnuplot, which draws every command's plots (drop_tests/formats/plot_runner.cpp). pandas only for the
# readers (read_sweep, read_dataset, read_stability), imported when used.
set(touchdown_python_depends "python3")
if(TOUCHDOWN_PYTHON AND DEFINED Python_VERSION_MINOR)  # the module is built for one CPython version
  math(EXPR touchdown_next_minor "${Python_VERSION_MINOR} + 1")
  set(touchdown_python_depends "python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}), \
python3 (<< ${Python_VERSION_MAJOR}.${touchdown_next_minor}), python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_DEPENDS "${touchdown_python_depends}, gnuplot-nox | gnuplot")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-pandas")
# A C++ program of one's own on the installed CMake package (find_package(touchdown)) also needs
# the headers of the libraries touchdown's headers include (cmake/touchdownConfig.cmake.in).
set(touchdown_dev_packages "g++, cmake, libeigen3-dev, libsundials-dev, libyaml-cpp-dev, nlohmann-json3-dev, \
libsqlite3-dev, libboost-dev, libceres-dev, libgmp-dev, libmpfr-dev")
if(TOUCHDOWN_WITH_MPI)
  string(APPEND touchdown_dev_packages ", libopenmpi-dev")
endif()
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "${touchdown_dev_packages}")
# `cpack` installs the build first through the `preinstall` target, which would otherwise build
# everything (tests, benchmarks, tools: most of a full build) before packaging what the quick start
# already built. Installs check instead that what they copy is built (touchdown_install_check).
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
include(CPack)

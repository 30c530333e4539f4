# `cmake --install BUILD --prefix P` (docs/install.md): the module libraries and their headers
# (touchdown_module, cmake/TouchdownModule.cmake), the touchdown executable, the data and the CMake
# package (P/lib/cmake/touchdown) whose targets are touchdown::touchdown and touchdown::<module>.
include(CMakePackageConfigHelpers)

install(TARGETS touchdown RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The executable finds it beside itself (drop_tests/io/catalog.cpp: DataDirectory).
install(DIRECTORY "${PROJECT_SOURCE_DIR}/data/" DESTINATION ${TOUCHDOWN_INSTALL_DATADIR})

# Flags the installed libraries need in the programs that link them (this tree's own targets get
# them from add_compile_options): the instruction set of a native build, where Eigen's alignment
# of fixed-size types follows it (a mismatch is a silent ABI break); the sanitizers' runtime.
if(TOUCHDOWN_NATIVE)
  target_compile_options(touchdown_rft INTERFACE $<INSTALL_INTERFACE:-march=native>)
endif()
if(TOUCHDOWN_SANITIZE OR TOUCHDOWN_FUZZ)
  target_link_options(touchdown_rft INTERFACE $<INSTALL_INTERFACE:-fsanitize=address,undefined>)
endif()

set(touchdown_config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/touchdown)
install(EXPORT touchdownTargets NAMESPACE touchdown:: DESTINATION ${touchdown_config_dir})
configure_package_config_file(cmake/touchdownConfig.cmake.in "${PROJECT_BINARY_DIR}/touchdownConfig.cmake"
  INSTALL_DESTINATION ${touchdown_config_dir}
  PATH_VARS TOUCHDOWN_INSTALL_DATADIR CMAKE_INSTALL_BINDIR)
# 0.x: a minor version may change the API, so only the same minor version is compatible.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/touchdownConfigVersion.cmake" COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/touchdownConfig.cmake" "${PROJECT_BINARY_DIR}/touchdownConfigVersion.cmake"
  DESTINATION ${touchdown_config_dir})

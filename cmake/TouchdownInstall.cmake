# `cmake --install BUILD --prefix P` (docs/install.md): the module libraries and their headers
# (touchdown_module, cmake/TouchdownModule.cmake), the touchdown executable, the data and the CMake
# package (P/lib/cmake/touchdown) whose targets are touchdown::touchdown and touchdown::<module>.
include(CMakePackageConfigHelpers)

touchdown_installs_target(touchdown)
install(TARGETS touchdown RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The executable finds it beside itself (drop_tests/catalog/catalog.cpp: DataDirectory).
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

# The first install rule (top-level CMakeLists.txt: it runs before those of the subdirectories):
# every built file the install copies must exist, or the install stops before copying anything and
# names the files and the targets to build. Without it an install of a build that made only some
# targets (`--target touchdown`) copied the libraries and stopped at the first missing one,
# leaving a prefix without bin/, share/ or lib/cmake/.
function(touchdown_write_install_check)
  get_property(targets GLOBAL PROPERTY TOUCHDOWN_INSTALLED_TARGETS)
  set(checks "")
  foreach(target ${targets})
    string(APPEND checks "if(NOT EXISTS \"$<TARGET_FILE:${target}>\")\n"
      "  list(APPEND missing \"$<TARGET_FILE:${target}>\")\nendif()\n")
  endforeach()
  file(GENERATE OUTPUT "${PROJECT_BINARY_DIR}/touchdown_install_check.cmake" CONTENT
"# Generated (cmake/TouchdownInstall.cmake): run first by `cmake --install`.
set(missing \"\")
${checks}if(missing)
  list(JOIN missing \"\\n  \" files)
  message(FATAL_ERROR \"nothing installed: not built yet:\\n  \${files}\\n\"
    \"Build them first: cmake --build ${PROJECT_BINARY_DIR} --target touchdown_quickstart (or the whole build)\")
endif()
")
endfunction()

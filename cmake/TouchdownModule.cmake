# touchdown_module(TARGET NAME): library TARGET is module NAME of the touchdown package
# (docs/install.md). Called in the module's own CMakeLists.txt, right after its add_library:
# - its headers are included as users write them (<rft/...>, <drop_tests/drop/...>): from the
#   source tree in this build, from <prefix>/include once installed;
# - touchdown::NAME names it, in this tree (an ALIAS: a misspelt name fails at configure time
#   instead of becoming a `-lname` link flag) and in the installed package (EXPORT_NAME);
# - `cmake --install` installs the library and the headers of the module's folder, keeping the
#   folder's path under include/.
function(touchdown_module target name)
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  add_library(touchdown::${name} ALIAS ${target})
  touchdown_installs_target(${target})
  install(TARGETS ${target} EXPORT touchdownTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
  install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/${folder}"
    FILES_MATCHING PATTERN "*.h")
endfunction()

# touchdown_installs_target(TARGET): `cmake --install` copies TARGET's file. An install first checks
# that every such file is built (touchdown_install_check, cmake/TouchdownInstall.cmake), so that one
# not built stops it before it copies anything rather than half-way.
function(touchdown_installs_target target)
  set_property(GLOBAL APPEND PROPERTY TOUCHDOWN_INSTALLED_TARGETS ${target})
endfunction()

# touchdown_stage_headers(TARGET FOLDER SCOPE): TARGET's include path holds FOLDER's headers and
# nothing else. FOLDER is a path relative to the source root ("rft", "lander/pad", "tests"); the
# build tree gets a folder of its own, include/FOLDER/, holding one symbolic link, FOLDER -> the
# source folder, and that folder goes on TARGET's include path with SCOPE (PUBLIC for a library, so
# a library that links it inherits it; PRIVATE for an executable). Headers keep their spelling
# ("rft/units.h", "lander/pad/rig_drop.h"), and a target sees exactly its own headers and those of
# the libraries it links: a header of a module above it or beside it is not found
# (tests/include_rules/ checks that).
function(touchdown_stage_headers target folder scope)
  set(root "${PROJECT_BINARY_DIR}/include/${folder}")
  get_filename_component(parent "${root}/${folder}" DIRECTORY)
  file(MAKE_DIRECTORY "${parent}")
  file(CREATE_LINK "${PROJECT_SOURCE_DIR}/${folder}" "${root}/${folder}" SYMBOLIC)
  if(scope STREQUAL "PRIVATE")
    target_include_directories(${target} PRIVATE "${root}")
  else()
    target_include_directories(${target} ${scope} $<BUILD_INTERFACE:${root}>)
  endif()
endfunction()

# touchdown_module(TARGET NAME): library TARGET is module NAME of the touchdown package
# (docs/install.md). Called in the module's own CMakeLists.txt, right after its add_library:
# - its headers are included as users write them (<rft/...>, <drop_tests/drop/...>): in this build
#   from its own staged folder (touchdown_stage_headers), so that it and its dependents see only
#   the headers of the modules they link; from <prefix>/include once installed;
# - touchdown::NAME names it, in this tree (an ALIAS: a misspelt name fails at configure time
#   instead of becoming a `-lname` link flag) and in the installed package (EXPORT_NAME);
# - `cmake --install` installs the library and the headers of the module's folder, keeping the
#   folder's path under include/.
function(touchdown_module target name)
  file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
  touchdown_stage_headers(${target} "${folder}" PUBLIC)
  target_include_directories(${target} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  add_library(touchdown::${name} ALIAS ${target})
  touchdown_installs_target(${target})
  install(TARGETS ${target} EXPORT touchdownTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/${folder}"
    FILES_MATCHING PATTERN "*.h")
endfunction()

# touchdown_installs_target(TARGET): `cmake --install` copies TARGET's file. An install first checks
# that every such file is built (touchdown_install_check, cmake/TouchdownInstall.cmake), so that one
# not built stops it before it copies anything rather than half-way.
function(touchdown_installs_target target)
  set_property(GLOBAL APPEND PROPERTY TOUCHDOWN_INSTALLED_TARGETS ${target})
endfunction()

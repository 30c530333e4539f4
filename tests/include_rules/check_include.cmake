# cmake -DCXX=COMPILER -DINCLUDES=DIR|DIR|... -DHEADER=HEADER -DEXPECT=found|missing -DWORK_DIR=DIR -P check_include.cmake
#
# Compiles (syntax only) a one-line source `#include "HEADER"` with the include path INCLUDES, a
# target's whole include path as its sources are compiled (tests/CMakeLists.txt passes
# $<TARGET_PROPERTY:target,INCLUDE_DIRECTORIES>, its dependencies' included). EXPECT=missing: the
# compiler must fail because HEADER is not found (a module that includes a header of a module
# above or beside it); EXPECT=found: it must compile (the control: the path itself works).
foreach(var CXX INCLUDES HEADER EXPECT WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_include.cmake: -D${var}=... is missing")
  endif()
endforeach()
string(REPLACE "|" ";" include_dirs "${INCLUDES}")
set(flags -std=c++20 -fsyntax-only)
foreach(dir ${include_dirs})
  if(NOT dir STREQUAL "")
    list(APPEND flags "-I${dir}")
  endif()
endforeach()
string(MAKE_C_IDENTIFIER "${HEADER}" stem)
set(source "${WORK_DIR}/include_${stem}.cpp")
file(WRITE "${source}" "#include \"${HEADER}\"\n")
execute_process(COMMAND "${CXX}" ${flags} "${source}" RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
# GCC says "HEADER: No such file or directory", Clang "'HEADER' file not found": either one means
# the compiler failed for the reason under test, not for another.
string(FIND "${out}" "${HEADER}: No such file" not_found)
if(not_found EQUAL -1)
  string(FIND "${out}" "'${HEADER}' file not found" not_found)
endif()
if(EXPECT STREQUAL "missing")
  if(status EQUAL 0 OR not_found EQUAL -1)
    message(FATAL_ERROR "expected \"${HEADER}\" not to be found on ${INCLUDES}; the compiler said (status ${status}):\n${out}")
  endif()
elseif(NOT status EQUAL 0)
  message(FATAL_ERROR "expected \"${HEADER}\" to compile on ${INCLUDES}; the compiler said (status ${status}):\n${out}")
endif()
message(STATUS "\"${HEADER}\" ${EXPECT} on the include path ${INCLUDES}")

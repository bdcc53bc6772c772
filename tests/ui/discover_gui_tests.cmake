# Run after a GUI test executable is built (tests/ui/CMakeLists.txt, add_gui_tests): asks it for its
# test functions with QtTest's own `-functions` (no C++ is parsed) and writes one ctest test
# PREFIX.FUNCTION per function into OUTPUT, which ctest includes.
# cmake -DEXE=... -DPREFIX=... -DTIMEOUT=... -DOUTPUT=... -P discover_gui_tests.cmake
execute_process(COMMAND ${CMAKE_COMMAND} -E env QT_QPA_PLATFORM=offscreen ${EXE} -functions
  OUTPUT_VARIABLE listing ERROR_VARIABLE errors RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXE} -functions failed (${status}): ${errors}")
endif()
string(REGEX MATCHALL "[A-Za-z_][A-Za-z0-9_]*\\(\\)" functions "${listing}")
if(NOT functions)
  message(FATAL_ERROR "${EXE} -functions listed no test function")
endif()
set(text "")
foreach(function IN LISTS functions)
  string(REPLACE "()" "" name "${function}")
  string(APPEND text "add_test([=[${PREFIX}.${name}]=] [=[${EXE}]=] [=[${name}]=])\n"
    "set_tests_properties([=[${PREFIX}.${name}]=] PROPERTIES LABELS gui TIMEOUT ${TIMEOUT} "
    "ENVIRONMENT QT_QPA_PLATFORM=offscreen)\n")
endforeach()
file(WRITE ${OUTPUT} "${text}")

# vplant_add_vcan_test(): register a CTest test that needs SocketCAN vcan interfaces.
#
#   vplant_add_vcan_test(NAME <name> COMMAND <cmd-or-target> [args...]
#                        [IFACES vcan0,vcan1]        # default: vcan0 (a ;-list works too)
#                        [TIMEOUT <seconds>]         # harness timeout, default 300
#                        [WORKING_DIRECTORY <dir>]   # default: the current binary dir
#                        [LABELS <label>...]         # added to "vcan"
#                        [ENVIRONMENT <VAR=value>...]
#                        [MERGE_OUTPUT])             # stderr into stdout, in order
#
# The command runs through tools/vcan/vcan-run: natively when the host kernel has vcan, else in
# a qemu guest (see docs/harness.md). If the first COMMAND word is a CMake target it is replaced
# by $<TARGET_FILE:...>; generator expressions work in every argument. The test gets
#   LABELS vcan;<LABELS>   RESOURCE_LOCK vcan   TIMEOUT <TIMEOUT + 60>
#   FIXTURES_REQUIRED vcan_guest (setup test vcan_harness_prepare: vcan-run --prepare-if-needed)
# and fails (never skips) when no vcan is to be had.

set(VPLANT_VCAN_RUN "${CMAKE_CURRENT_LIST_DIR}/../tools/vcan/vcan-run")
get_filename_component(VPLANT_VCAN_RUN "${VPLANT_VCAN_RUN}" ABSOLUTE)
set(VPLANT_VCAN_RUN "${VPLANT_VCAN_RUN}" CACHE INTERNAL "tools/vcan/vcan-run")
set(VPLANT_VCAN_DEFAULT_TIMEOUT 300 CACHE STRING "Default vcan-run --timeout (s) of vplant_add_vcan_test")

# The setup fixture: builds the guest kernel cache once per ctest run if qemu mode needs it
# (a few seconds; ~1 s download + unpack on a clean machine), so no test pays for it in its timeout.
function(_vplant_vcan_fixture)
  get_property(done GLOBAL PROPERTY VPLANT_VCAN_FIXTURE_DEFINED)
  if(done)
    return()
  endif()
  set_property(GLOBAL PROPERTY VPLANT_VCAN_FIXTURE_DEFINED TRUE)
  add_test(NAME vcan_harness_prepare COMMAND "${VPLANT_VCAN_RUN}" --prepare-if-needed)
  set_tests_properties(vcan_harness_prepare PROPERTIES
    LABELS "vcan"
    FIXTURES_SETUP vcan_guest
    RESOURCE_LOCK vcan
    TIMEOUT 900)
endfunction()

function(vplant_add_vcan_test)
  cmake_parse_arguments(PARSE_ARGV 0 V "MERGE_OUTPUT" "NAME;IFACES;TIMEOUT;WORKING_DIRECTORY"
                        "COMMAND;LABELS;ENVIRONMENT")
  if(V_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "vplant_add_vcan_test: unexpected arguments: ${V_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT V_NAME)
    message(FATAL_ERROR "vplant_add_vcan_test: NAME is required")
  endif()
  if(NOT V_COMMAND)
    message(FATAL_ERROR "vplant_add_vcan_test(${V_NAME}): COMMAND is required")
  endif()

  if(NOT V_IFACES)
    set(V_IFACES vcan0)
  endif()
  string(REPLACE ";" "," ifaces "${V_IFACES}")
  if(NOT ifaces MATCHES "^[A-Za-z0-9_.-]+(,[A-Za-z0-9_.-]+)*$")
    message(FATAL_ERROR "vplant_add_vcan_test(${V_NAME}): bad IFACES '${V_IFACES}'")
  endif()

  if(NOT V_TIMEOUT)
    set(V_TIMEOUT ${VPLANT_VCAN_DEFAULT_TIMEOUT})
  endif()
  if(NOT V_TIMEOUT MATCHES "^[0-9]+$" OR V_TIMEOUT EQUAL 0)
    message(FATAL_ERROR "vplant_add_vcan_test(${V_NAME}): TIMEOUT must be a positive integer")
  endif()
  # vcan-run's own timeout fires first, with a clear message and exit 124; CTest's is a backstop.
  math(EXPR ctest_timeout "${V_TIMEOUT} + 60")

  if(NOT V_WORKING_DIRECTORY)
    set(V_WORKING_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}")
  endif()

  # add_test only resolves a target name in its first word, which is vcan-run here.
  list(GET V_COMMAND 0 first)
  if(TARGET "${first}")
    get_target_property(type "${first}" TYPE)
    if(type STREQUAL "EXECUTABLE")
      list(REMOVE_AT V_COMMAND 0)
      list(PREPEND V_COMMAND "$<TARGET_FILE:${first}>")
    endif()
  endif()

  set(opts --ifaces "${ifaces}" --timeout "${V_TIMEOUT}")
  if(V_MERGE_OUTPUT)
    list(APPEND opts --merge-output)
  endif()

  _vplant_vcan_fixture()
  add_test(NAME "${V_NAME}"
    COMMAND "${VPLANT_VCAN_RUN}" ${opts} -- ${V_COMMAND}
    WORKING_DIRECTORY "${V_WORKING_DIRECTORY}")
  set(labels vcan ${V_LABELS})
  # RUN_SERIAL: the guest is emulated (TCG) and the tests check wall-clock periods (heartbeats at
  # 100 ms ± 15); a browser test beside it on a 2-core machine stretches them to 150 ms.
  set_tests_properties("${V_NAME}" PROPERTIES
    LABELS "${labels}"
    RESOURCE_LOCK vcan
    RUN_SERIAL TRUE
    FIXTURES_REQUIRED vcan_guest
    TIMEOUT ${ctest_timeout})
  if(V_ENVIRONMENT)
    set_tests_properties("${V_NAME}" PROPERTIES ENVIRONMENT "${V_ENVIRONMENT}")
  endif()
endfunction()

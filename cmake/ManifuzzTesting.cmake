# CTest helpers for a generator tested with manifuzz.
#
#   manifuzz_add_regression_tests(TARGET <plugin target> DIRECTORY <dir>
#                                 [PREFIX <test name prefix>] [PROFILE <profile>])
#
# Adds one test per <dir>/*.case: `manifuzz replay --generator <plugin> CASE`,
# which fails when the case's verdict is a violation (exit 1) or the case
# cannot be read (exit 2). PROFILE passes --profile to every replay.
function(manifuzz_add_regression_tests)
  cmake_parse_arguments(MFZ "" "TARGET;DIRECTORY;PREFIX;PROFILE" "" ${ARGN})
  if(NOT MFZ_TARGET OR NOT MFZ_DIRECTORY)
    message(FATAL_ERROR "manifuzz_add_regression_tests needs TARGET and DIRECTORY")
  endif()
  if(NOT TARGET manifuzz::manifuzz)
    message(FATAL_ERROR "manifuzz_add_regression_tests: no manifuzz::manifuzz program (find_package(manifuzz) first)")
  endif()
  if(NOT DEFINED MFZ_PREFIX)
    set(MFZ_PREFIX "${MFZ_TARGET}.")
  endif()
  set(profile)
  if(MFZ_PROFILE)
    set(profile --profile "${MFZ_PROFILE}")
  endif()
  file(GLOB cases CONFIGURE_DEPENDS "${MFZ_DIRECTORY}/*.case")
  if(NOT cases)
    message(WARNING "manifuzz_add_regression_tests: no .case files in ${MFZ_DIRECTORY}")
  endif()
  foreach(case ${cases})
    get_filename_component(name "${case}" NAME_WE)
    add_test(NAME "${MFZ_PREFIX}${name}"
             COMMAND manifuzz::manifuzz replay --generator "$<TARGET_FILE:${MFZ_TARGET}>" ${profile} "${case}")
  endforeach()
endfunction()

# aco_discover_tests(<target> [FAST_UNLESS tag...] [catch_discover_tests options...])
# One CTest test per Catch2 test case of <target> (catch_discover_tests), each labelled with its
# Catch2 tags without brackets: `ctest -L plugins` runs the tests tagged [plugins]. With
# FAST_UNLESS, a test carrying none of those tags is labelled `fast` too. Catch2 v2's
# discovery sets no labels, and its listing wraps long names, so the labels come from one
# `<target> "[tag]" --list-test-names-only` per tag, written after each build into a file that
# ctest reads after the tests' own. Used by this project's tests and, installed with the SDK
# (find_package(aco) defines it), by the tests that aco-new-plugin scaffolds.
if(CMAKE_SCRIPT_MODE_FILE)
  # cmake -D EXECUTABLE=... -D OUTPUT=... [-D SLOW_TAGS=a,b] -P AcoCatchLabels.cmake: writes OUTPUT.
  cmake_policy(VERSION 3.25)
  execute_process(COMMAND "${EXECUTABLE}" --list-tags OUTPUT_VARIABLE listing RESULT_VARIABLE status)
  if(status LESS 0)
    message(FATAL_ERROR "${EXECUTABLE} --list-tags failed: ${listing}")
  endif()
  string(REGEX MATCHALL "\\[[^]\n]+\\]" tags "${listing}")
  string(REPLACE "," ";" slow_tags "${SLOW_TAGS}")
  # The names of the tests a spec selects, as list items; each is keyed by its hash below, since
  # names hold any character.
  function(test_names spec out)
    execute_process(COMMAND "${EXECUTABLE}" ${spec} --list-test-names-only OUTPUT_VARIABLE names)
    string(REPLACE ";" "\\;" names "${names}")
    string(REPLACE "\n" ";" names "${names}")
    list(REMOVE_ITEM names "")
    set(${out} "${names}" PARENT_SCOPE)
  endfunction()
  test_names("" names)
  set(tests "")
  foreach(name IN LISTS names)
    string(MD5 key "${name}")
    list(APPEND tests "${key}")
    set(name_${key} "${name}")
  endforeach()
  foreach(tag IN LISTS tags)
    string(REGEX REPLACE "^\\[(.*)\\]$" "\\1" label "${tag}")
    test_names("${tag}" names)
    foreach(name IN LISTS names)
      string(MD5 key "${name}")
      list(APPEND labels_${key} "${label}")
      if(label IN_LIST slow_tags)
        set(slow_${key} TRUE)
      endif()
    endforeach()
  endforeach()
  set(script "")
  foreach(key IN LISTS tests)
    if(DEFINED SLOW_TAGS AND NOT slow_${key})
      list(APPEND labels_${key} fast)
    endif()
    string(APPEND script "set_tests_properties([==[${name_${key}}]==] PROPERTIES LABELS [==[${labels_${key}}]==])\n")
  endforeach()
  file(WRITE "${OUTPUT}" "${script}")
  return()
endif()

function(aco_discover_tests target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "FAST_UNLESS")
  include(Catch)  # here, not above: Catch2's module folder is known once find_package(Catch2) ran
  catch_discover_tests(${target} ${arg_UNPARSED_ARGUMENTS})
  set(labels_file "${CMAKE_CURRENT_BINARY_DIR}/${target}_labels.cmake")
  set(fast "")
  if(DEFINED arg_FAST_UNLESS)
    string(REPLACE ";" "," slow_tags "${arg_FAST_UNLESS}")
    set(fast -D "SLOW_TAGS=${slow_tags}")
  endif()
  add_custom_command(TARGET ${target} POST_BUILD
    COMMAND "${CMAKE_COMMAND}" -D "EXECUTABLE=$<TARGET_FILE:${target}>" -D "OUTPUT=${labels_file}" ${fast}
            -P "${CMAKE_CURRENT_FUNCTION_LIST_FILE}"
    VERBATIM)
  # After catch_discover_tests' own include file, which defines the tests.
  set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${labels_file}")
endfunction()

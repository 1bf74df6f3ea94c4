# hazard_program(<target> SUMMARY "<one line>")
# Declares one of the installed programs: installed into bin/, listed in programs.txt (build.sh
# links each into the tree's bin/ folder from it) and given a man page generated from its own
# --help, --version, --example and --interface (cmake/man_page.cmake), so the page cannot drift
# from the program, and linked with the programs' allocator (cmake/allocator.cmake). SUMMARY is
# the man page's NAME line.
function(hazard_program target)
  cmake_parse_arguments(PARSE_ARGV 1 ARG "" "SUMMARY" "")
  if(NOT ARG_SUMMARY)
    message(FATAL_ERROR "hazard_program(${target}): SUMMARY is required")
  endif()
  hazard_use_allocator(${target})
  install(TARGETS ${target} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT programs)
  set_property(GLOBAL APPEND PROPERTY HAZARD_PROGRAMS ${target})
  set_property(GLOBAL PROPERTY HAZARD_PROGRAM_SUMMARY_${target} "${ARG_SUMMARY}")
endfunction()

# After every program is declared: programs.txt ("<name> <path>" a line) and the man pages.
function(hazard_finish_programs)
  get_property(programs GLOBAL PROPERTY HAZARD_PROGRAMS)
  list(SORT programs)
  set(lines "")
  foreach(program ${programs})
    string(APPEND lines "${program} $<TARGET_FILE:${program}>\n")
  endforeach()
  file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/programs.txt CONTENT "${lines}")
  if(HAZARD_MAN_PAGES)
    hazard_man_pages(${programs})
  endif()
endfunction()

function(hazard_man_pages)
  find_program(HAZARD_HELP2MAN help2man)
  find_program(HAZARD_GZIP gzip)
  if(NOT HAZARD_HELP2MAN OR NOT HAZARD_GZIP)
    message(FATAL_ERROR "the man pages need help2man and gzip (./build.sh deps installs them), "
                        "or configure with -DHAZARD_MAN_PAGES=OFF")
  endif()
  set(pages "")
  foreach(program ${ARGN})
    get_property(summary GLOBAL PROPERTY HAZARD_PROGRAM_SUMMARY_${program})
    set(page ${PROJECT_BINARY_DIR}/man/${program}.1.gz)
    add_custom_command(
      OUTPUT ${page}
      COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${program}> -DNAME=${program}
              "-DSUMMARY=${summary}" "-DSOURCE=HazardSensor ${PROJECT_VERSION}"
              -DHELP2MAN=${HAZARD_HELP2MAN}
              -DGZIP=${HAZARD_GZIP} -DOUTPUT=${page}
              -P ${PROJECT_SOURCE_DIR}/cmake/man_page.cmake
      DEPENDS ${program} ${PROJECT_SOURCE_DIR}/cmake/man_page.cmake
      COMMENT "Man page of ${program}"
      VERBATIM)
    list(APPEND pages ${page})
  endforeach()
  add_custom_target(man_pages ALL DEPENDS ${pages})
  install(FILES ${pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT programs)
endfunction()

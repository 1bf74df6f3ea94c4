# Writes one program's man page (cmake -P): help2man reads the program's --help and --version;
# its --example and --interface texts, when it has them, become the EXAMPLE and INTERFACE
# sections. Variables: PROGRAM (path), NAME, SUMMARY, SOURCE, HELP2MAN, GZIP, OUTPUT (.1.gz).

# A text as roff that shows it as printed: no fill, backslashes and leading dots escaped.
function(as_roff_block text out_var)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out_var} ".nf\n${text}\n.fi\n" PARENT_SCOPE)
endfunction()

# The text a switch prints, or "" when the program has no such switch (non-zero exit).
function(information_text switch out_var)
  execute_process(COMMAND ${PROGRAM} ${switch} OUTPUT_VARIABLE text ERROR_QUIET
                  RESULT_VARIABLE status TIMEOUT 30)
  # Colour codes, if a program printed any, are no part of a page.
  string(ASCII 27 escape)
  string(REGEX REPLACE "${escape}\\[[0-9;]*m" "" text "${text}")
  if(NOT status EQUAL 0)
    set(text "")
  endif()
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

get_filename_component(work ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${work})
set(include_file ${work}/${NAME}.h2m)
set(sections "")
foreach(pair "--example;EXAMPLE" "--interface;INTERFACE")
  list(GET pair 0 switch)
  list(GET pair 1 section)
  information_text(${switch} text)
  if(NOT text STREQUAL "")
    as_roff_block("${text}" block)
    string(APPEND sections "[${section}]\n${block}")
  endif()
endforeach()
set(include_option "")
if(NOT sections STREQUAL "")
  file(WRITE ${include_file} "${sections}")
  set(include_option --include=${include_file})
endif()

set(page ${work}/${NAME}.1)
execute_process(
  COMMAND ${HELP2MAN} --no-info --no-discard-stderr --section=1 "--name=${SUMMARY}"
          "--source=${SOURCE}" "--manual=User Commands" ${include_option}
          --output=${page} ${PROGRAM}
  RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "help2man failed for ${NAME}: ${error}")
endif()
execute_process(COMMAND ${GZIP} -9nf ${page} RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "gzip failed for ${page}")
endif()

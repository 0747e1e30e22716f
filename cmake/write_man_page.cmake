# Run by fooball_man_page (FooBallManPage.cmake) as cmake -P with PROGRAM, DESCRIPTION,
# SUBCOMMANDS (comma-separated, may be empty), VERSION, HELP2MAN and OUTPUT (…/NAME.1.gz).

# A sanitizer build's programs would report Qt's and the C library's leftovers at exit, which
# help2man takes for a failure.
set(ENV{ASAN_OPTIONS} "detect_leaks=0")
get_filename_component(directory ${OUTPUT} DIRECTORY)
get_filename_component(name ${PROGRAM} NAME)
file(MAKE_DIRECTORY ${directory})

# help2man's include file: each subcommand's --help, verbatim (.nf … .fi), under COMMANDS.
set(include_option)
if(SUBCOMMANDS)
  set(include_file ${directory}/${name}.h2m)
  set(include_option --include=${include_file})
  file(WRITE ${include_file} "[COMMANDS]\n")
  string(REPLACE "," ";" subcommands "${SUBCOMMANDS}")
  foreach(subcommand IN LISTS subcommands)
    execute_process(COMMAND ${PROGRAM} ${subcommand} --help OUTPUT_VARIABLE help
                    RESULT_VARIABLE result)
    if(NOT result EQUAL 0)
      message(FATAL_ERROR "${name} ${subcommand} --help failed (${result})")
    endif()
    # roff: a backslash is \e, and a line may not start with a control character.
    string(REPLACE "\\" "\\e" help "${help}")
    string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
    file(APPEND ${include_file} ".SS \"${name} ${subcommand}\"\n.nf\n${help}.fi\n")
  endforeach()
endif()

set(page ${directory}/${name}.1)
execute_process(
  # Both programs' --version says "fooball X.Y.Z", from which help2man would title both pages
  # "fooball": name each page after its program instead, in help2man's "PROGRAM (PACKAGE)
  # VERSION" form.
  COMMAND ${HELP2MAN} --no-info --no-discard-stderr "--name=${DESCRIPTION}"
          "--version-string=${name} (FooBall) ${VERSION}" ${include_option} --output=${page}
          ${PROGRAM}
  RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "help2man failed for ${name} (${result})")
endif()
# gzip -n: no name or time stamp inside, so the same page gives the same bytes.
execute_process(COMMAND gzip -9nf ${page} RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "gzip failed for ${page} (${result})")
endif()

# fooball_man_page(<program> DESCRIPTION <one line> [SUBCOMMANDS <name>...])
# Writes man/<program>.1.gz from the program's own --help with help2man (each subcommand's
# --help becomes a subsection of COMMANDS), and installs it in share/man/man1. The page is
# rebuilt whenever the program is, so it never lags its --help.
find_program(FOOBALL_HELP2MAN help2man REQUIRED)
set(FOOBALL_MAN_PAGE_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/write_man_page.cmake)

function(fooball_man_page program)
  cmake_parse_arguments(ARG "" "DESCRIPTION" "SUBCOMMANDS" ${ARGN})
  set(page ${CMAKE_CURRENT_BINARY_DIR}/man/${program}.1.gz)
  # A list would split into several arguments on the command line: pass it comma-separated.
  string(REPLACE ";" "," subcommands "${ARG_SUBCOMMANDS}")
  add_custom_command(
    OUTPUT ${page}
    COMMAND ${CMAKE_COMMAND} -DPROGRAM=$<TARGET_FILE:${program}> "-DDESCRIPTION=${ARG_DESCRIPTION}"
            "-DSUBCOMMANDS=${subcommands}" -DVERSION=${PROJECT_VERSION} -DHELP2MAN=${FOOBALL_HELP2MAN} -DOUTPUT=${page}
            -P ${FOOBALL_MAN_PAGE_SCRIPT}
    DEPENDS ${program} ${FOOBALL_MAN_PAGE_SCRIPT}
    COMMENT "Writing the man page of ${program}"
    VERBATIM)
  add_custom_target(${program}_man_page ALL DEPENDS ${page})
  install(FILES ${page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
endfunction()

# Writes chainbreak.1 (roff) from the help text the built program prints: `EXE --help` for the
# synopsis and `EXE <command> --help` for each command. Run with cmake -P at build time:
#   -DEXE=path/to/chainbreak -DOUT=chainbreak.1 -DVERSION=0.1
set(COMMANDS run sweep snapshot render figures)

# Help text as a roff no-fill block: backslashes escaped, lines that roff would read as
# requests (starting with . or ') protected.
function(help_block out_var)
  execute_process(COMMAND ${EXE} ${ARGN} --help OUTPUT_VARIABLE text RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${EXE} ${ARGN} --help failed (${status})")
  endif()
  string(REPLACE "${EXE}" "chainbreak" text "${text}")  # argv[0] as the user types it
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out_var} ".nf\n${text}.fi\n" PARENT_SCOPE)
endfunction()

help_block(main)
execute_process(COMMAND ${EXE} --version OUTPUT_VARIABLE version OUTPUT_STRIP_TRAILING_WHITESPACE)
set(page ".TH CHAINBREAK 1 \"\" \"chainbreak ${VERSION}\" \"User Commands\"\n")
string(APPEND page ".SH NAME\nchainbreak \\- which part of a harmonic chain breaks: simulate, sweep, render\n")
string(APPEND page ".SH SYNOPSIS\n.B chainbreak\n\\fICOMMAND\\fR [\\fIOPTIONS\\fR]\n.br\n.B chainbreak\n--version\n")
string(APPEND page ".SH DESCRIPTION\n${main}")
string(APPEND page ".SH COMMANDS\n")
foreach(command ${COMMANDS})
  help_block(block ${command})
  string(APPEND page ".SS ${command}\n${block}")
endforeach()
string(APPEND page ".SS view\nThe real-time window is its own program, chainbreak-view; see\n.B chainbreak view SCENE --help\n")
string(APPEND page ".SH EXIT STATUS\n0 success, 1 the run failed (non-finite state), 2 a mistake in the scene or the options, 130 interrupted.\n")
string(APPEND page ".SH FILES\nExample scenes: /usr/share/chainbreak/scenes (under the install prefix).\n")
string(APPEND page ".SH VERSION\n${version}\n")
file(WRITE ${OUT}.tmp "${page}")
file(RENAME ${OUT}.tmp ${OUT})

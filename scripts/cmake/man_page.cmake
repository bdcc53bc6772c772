# Script mode (cmake -P): writes the man page OUTPUT from PROGRAM's --help, so the page lists
# exactly the options the program accepts (app/program_usage.cpp). VERSION goes into the footer;
# PREFIX, DATADIR and DOCDIR (the installation's absolute prefix and its GNUInstallDirs folders)
# give the FILES section's paths.
execute_process(COMMAND ${PROGRAM} --help
  OUTPUT_VARIABLE help RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --help failed (${rc}): ${err}")
endif()
foreach(dir DATADIR DOCDIR)
  if(NOT IS_ABSOLUTE "${${dir}}")
    set(${dir} "${PREFIX}/${${dir}}")
  endif()
endforeach()
# roff: backslashes and hyphens escaped, a line starting with . or ' kept as text
function(roff_escape text out)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()
roff_escape("${help}" help)
roff_escape("${DATADIR}" datadir)
roff_escape("${DOCDIR}" docdir)
file(WRITE ${OUTPUT} ".TH CHAPLYGIN\\-LAB 1 \"\" \"Chaplygin Lab ${VERSION}\" \"User Commands\"
.SH NAME
chaplygin\\-lab \\- steer nonholonomic Chaplygin systems along a path
.SH SYNOPSIS
.B chaplygin\\-lab
[\\fIFILE\\fR | \\fIscene options\\fR] [\\-\\-presentation]
.br
.B chaplygin\\-lab \\-\\-screenshot
\\fIFILE.png\\fR [\\-\\-size \\fIW\\fRx\\fIH\\fR] [\\-\\-at \\fIT\\fR] [\\-\\-panel \\fIDOCK\\fR] [\\-\\-presentation] [\\-\\-language \\fICODE\\fR] [\\fIscene options\\fR]
.br
.B chaplygin\\-lab \\-\\-headless
[\\fIscene options\\fR] [\\fIoutput options\\fR]
.br
.B chaplygin\\-lab
\\-\\-help | \\-\\-version
.SH DESCRIPTION
Chaplygin Lab steers a Chaplygin sleigh, a rolling disk or a two\\-wheeled carriage along a path
with the tracking control of Antunes, Sigaud and de Moraes (2009), next to the free motion.
Without \\fB\\-\\-headless\\fR it opens the desktop window, with a scene file or the scene options
below; \\fB\\-\\-screenshot\\fR renders that window offscreen to a PNG file and exits.
.SH OPTIONS
The command line, as \\fBchaplygin\\-lab \\-\\-help\\fR prints it:
.PP
.nf
${help}.fi
.SH FILES
.TP
.I ${datadir}/chaplygin\\-lab/scenes
the paper's examples (presets) and the gallery of failing methods, as scene files for
\\fB\\-\\-scene\\fR or File \\(-> Open
.TP
.I ${datadir}/chaplygin\\-lab/translations
the catalogues of the window's languages (View \\(-> Language)
.TP
.I ${datadir}/mime/packages/io.github.chaplyginlab.ChaplyginLab.xml
the scene file type, application/x\\-chaplygin\\-scene+json
.SH SEE ALSO
The user guide, physics and numerics notes in \\fI${docdir}\\fR.
")

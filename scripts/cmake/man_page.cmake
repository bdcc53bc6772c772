# Script mode (cmake -P): writes the man page OUTPUT from PROGRAM's --headless --help, so the
# page lists exactly the options the program accepts. VERSION goes into the page's footer.
execute_process(COMMAND ${PROGRAM} --headless --help
  OUTPUT_VARIABLE help RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} --headless --help failed (${rc}): ${err}")
endif()
# roff: backslashes and hyphens escaped, a line starting with . or ' kept as text
string(REPLACE "\\" "\\e" help "${help}")
string(REPLACE "-" "\\-" help "${help}")
string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" help "${help}")
file(WRITE ${OUTPUT} ".TH CHAPLYGIN\\-LAB 1 \"\" \"Chaplygin Lab ${VERSION}\" \"User Commands\"
.SH NAME
chaplygin\\-lab \\- steer nonholonomic Chaplygin systems along a path
.SH SYNOPSIS
.B chaplygin\\-lab
[\\fIFILE\\fR | \\fIscene options\\fR]
.br
.B chaplygin\\-lab \\-\\-headless
[\\fIoptions\\fR]
.br
.B chaplygin\\-lab \\-\\-screenshot
\\fIFILE\\fR [\\-\\-size \\fIW\\fRx\\fIH\\fR] [\\-\\-at \\fIT\\fR] [\\-\\-panel path|parameters|methods] [\\fIscene options\\fR]
.SH DESCRIPTION
Chaplygin Lab steers a Chaplygin sleigh, a rolling disk or a two\\-wheeled carriage along a path
with the tracking control of Antunes, Sigaud and de Moraes (2009), next to the free motion.
Without \\fB\\-\\-headless\\fR it opens the desktop window, with a scene file or the scene options
below; \\fB\\-\\-screenshot\\fR renders that window offscreen to a PNG file and exits.
.SH OPTIONS
The command line, as \\fBchaplygin\\-lab \\-\\-headless \\-\\-help\\fR prints it:
.PP
.nf
${help}.fi
.SH FILES
.TP
.I share/chaplygin\\-lab/scenes
the paper's examples (presets) and the gallery of failing methods, as scene files for
\\fB\\-\\-scene\\fR or File \\(-> Open
.SH SEE ALSO
The user guide, physics and numerics notes in \\fIshare/doc/chaplygin\\-lab\\fR.
")

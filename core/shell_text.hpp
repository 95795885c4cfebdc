// Text written into the shell scripts granshock emits (docs/study.md, "Slurm") and into the
// commands it tells a user to type ("continue with --resume: granshock run ..."). A script
// line ends only where granshock ends it: no value written into a script, a comment
// included, may hold a raw control character (a newline would end a comment and start a
// command; a carriage return makes sbatch refuse the script).
#pragma once

#include <string>

namespace granshock {

// `text` as one bash word: '...' (a quote written '\''), or $'...' with \xHH escapes when
// `text` holds a control character, so that the word is on one line of the script.
std::string shell_quote(const std::string& text);

// `text` for a comment line: each control character written as \xHH, and '\' as "\\".
std::string comment_text(const std::string& text);

// Whether `text` holds a control character (below 0x20, or 0x7f).
bool has_control_character(const std::string& text);

// Whether `text` can stand unquoted in an #SBATCH line: printable ASCII without blanks,
// quotes, '\', '$', '#' and '%' (sbatch's own replacement symbols).
bool sbatch_plain(const std::string& text);

}  // namespace granshock

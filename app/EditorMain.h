#pragma once

namespace pf {

// `paperfold [--lang CODE] [sheet.paper]`: the desktop editor.
int runEditor(int argc, char* argv[]);

} // namespace pf

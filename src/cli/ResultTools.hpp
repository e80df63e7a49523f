#pragma once
// Command-line tools on result files, besides `run` (docs/visualisation.md):
//   miniaster convert RESULT.rmed OUT.vtu
//   miniaster plot RESULT.rmed [--field NAME] [--component C] [--deformed SCALE] -o OUT.png
// Both return the process exit status (0, or 1 with one message on stderr).
namespace ma::cli {

int convertMain(int argc, char** argv);
int plotMain(int argc, char** argv);

}  // namespace ma::cli

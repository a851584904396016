#pragma once
// omnitune-calibrate colours --profile-list / --profile-save NAME / --profile-load NAME: the
// window's venue profiles (calib/colour/ColourProfile.h) on the command line, beside --config.
#include "app/CommandLine.h"

namespace omnitune {

// Whether the command line asks for a profile operation.
bool wantsColourProfile(const CommandLine& cl);
// Runs it: 0 on success, 1 with a one-line reason on stderr.
int runColourProfile(const CommandLine& cl);

}  // namespace omnitune

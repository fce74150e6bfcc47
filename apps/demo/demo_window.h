// `pathlab-demo NAME --gui`: the demo live in the debugger's window shell,
// its parameters as sliders, the figure redrawn as they move.
#pragma once

#include <string>

#include "demos.h"

namespace pathlab::demo {

// Runs the window on `demo` (the others are a click away); with a
// screenshot path, saves the first finished frame there and returns.
int runDemoWindow(const Demo& demo, const Values& values, const std::string& screenshot);

}  // namespace pathlab::demo

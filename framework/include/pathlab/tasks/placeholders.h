// Task 7 is a placeholder until their issues land: each file defines one
// function that reports "not implemented" once. The renderer calls them at
// start-up so every build says plainly which tasks are still missing.
#pragma once

namespace pathlab {

void environmentPlaceholder();      // tasks/07-environment/environment.cpp

}  // namespace pathlab

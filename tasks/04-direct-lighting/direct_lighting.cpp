// Task 4 — placeholder. This task's student file and reference arrive with
// its own issue; until then the renderer says once that it is missing.
#include "pathlab/tasks/placeholders.h"
#include "pathlab/todo.h"

namespace pathlab {

void directLightingPlaceholder() { PATHLAB_TODO("T4"); }

}  // namespace pathlab

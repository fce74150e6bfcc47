// Task 6 — placeholder. This task's student file and reference arrive with
// its own issue; until then the renderer says once that it is missing.
#include "pathlab/tasks/placeholders.h"
#include "pathlab/todo.h"

namespace pathlab {

void mirrorGlassPlaceholder() { PATHLAB_TODO("T6"); }

}  // namespace pathlab

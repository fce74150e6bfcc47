// attack: a file whose compilation prints hundreds of megabytes of errors (262,144 arrays of
// negative size, each with its macro-expansion notes), to fill the grader's memory
// base: none  expect: 0
#define PATHLAB_E2(x) x x
#define PATHLAB_E8(x) PATHLAB_E2(PATHLAB_E2(PATHLAB_E2(x)))
#define PATHLAB_E512(x) PATHLAB_E8(PATHLAB_E8(PATHLAB_E8(x)))
#define PATHLAB_FLOOD \
  PATHLAB_E512(PATHLAB_E512(int pathlab_flood_xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx[-1];))
void pathlabFlood() { PATHLAB_FLOOD }

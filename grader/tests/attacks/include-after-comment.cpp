// attack: a directive after a comment on the same line, and a path built by a macro
// base: reference  expect: 0
#define PATHLAB_STRINGIZE(x) #x
#define PATHLAB_PATH(x) PATHLAB_STRINGIZE(x)
/* */ #include PATHLAB_PATH(@LEAK@)

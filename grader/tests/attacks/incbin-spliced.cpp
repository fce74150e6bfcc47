// attack: the assembler's .incbin spelled in two string pieces, which no text check of the source
// finds, embeds a file and prints it when the candidate starts
// base: reference  expect: 0
#include <cstdio>
asm(".section .rodata\n.global leaked\nleaked:\n.inc" "bin \"@LEAK@\"\n.byte 0\n.text");
extern "C" const char leaked[];
static int print_leaked = [] { std::printf("%s\n", leaked); return 0; }();

// attack: an object file whose sections a host's toolchain would act on: GCC LTO IR (lto-ir.inc, compiled
// by the test), written as arrays in sections named .gnu.lto_* (no inline assembly in the file itself).
// Linked outside the sandbox, GCC's linker plugin claimed it and compiled it, as root, with no time limit:
// the IR's assembly read the reference into the candidate (fails before the link moved into the sandbox)
// base: none  expect: 0  lto: lto-ir.inc
@LTO_SECTIONS@

// attack: embeds the reference source at compile time with the assembler's .incbin
// base: stub  expect: 0
asm(".section .rodata\n.global stolen\nstolen:\n.incbin \"@ROOT@/solutions/01-camera-rays/camera_rays.cpp\"\n.byte 0\n.text");

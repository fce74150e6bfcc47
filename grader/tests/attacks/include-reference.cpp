// attack: includes the reference through a relative path and through the absolute path of the repository
// base: none  expect: 0
#include "../../solutions/01-camera-rays/camera_rays.cpp"
#include "@ROOT@/solutions/01-camera-rays/camera_rays.cpp"

#pragma once
// The program's version, from CMake's project(VERSION ...). Checkpoints, partial renders and
// image metadata carry it, so a file is never resumed or merged by a program that might render
// its scene differently. Bump it whenever a change alters the image of any scene and settings.

namespace wt {

const char* program_version();

}  // namespace wt

#pragma once
// EXR and PNG files written here, through OpenEXR and libpng, instead of through the image I/O
// module (image_module_abi.h). Those are the formats a render writes by default, and loading the
// module costs a process a few hundred milliseconds before the first byte: Debian's
// OpenImageIO brings some 260 libraries whose symbols the dynamic loader binds (OpenVDB's alone
// over 50,000) and whose static constructors run. OpenEXR and libpng are what OpenImageIO
// itself writes these formats with; linked directly they cost a few milliseconds.
//
// Each writer takes the module's own description of an image (WtImageToWrite), attributes
// named as OpenImageIO names them, and writes what OpenImageIO's writer of that format would:
// reading the file back through the module gives the same channels, values and attributes
// (tests/image_output_test.cpp compares the two). Other formats (.hdr, .jpg) still go through
// the module.

#include <string>

#include "core/image_io/image_error.h"
#include "core/image_io/image_module_abi.h"

namespace wt {

// Each writes `image` to image.path and throws ImageError naming it if that fails. write_exr
// takes float pixels (any channels; the Z channel is depth), write_png 8-bit ones (1 to 4
// channels). Attributes: see each .cpp for which it keeps and under what name.
void write_exr(const WtImageToWrite& image);  // exr_output.cpp
void write_png(const WtImageToWrite& image);  // png_output.cpp

}  // namespace wt

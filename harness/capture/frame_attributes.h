// The glint.* header attributes of a frame file (docs/capture-format.md, "Attributes"),
// plus the standard OpenEXR worldToCamera / worldToNDC attributes written for other tools.
// Internal to the capture library.
#pragma once

#include "capture/capture_frame.h"

#include <Imath/ImathMatrix.h>
#include <OpenEXR/ImfHeader.h>

#include <filesystem>

namespace glint::capture {

// glint.* matrices are stored transposed so that they are proper Imath (row-vector)
// transforms: p·M in Imath equals M·p in glint. Doubles, so the round trip is exact.
Imath::M44d toImath(const Mat4& m);
Mat4 fromImath(const Imath::M44d& m);

// OpenEXR's worldToCamera (left-handed: +x right, +y up, +z forward) and worldToNDC
// (RenderMan NDC: (0,0) top-left and (1,1) bottom-right of the image, after the projective
// divide; z keeps device depth), both row-vector float matrices derived from the camera.
Imath::M44f worldToCameraOf(const Camera& camera);
Imath::M44f worldToNdcOf(const Camera& camera);

void writeFrameAttributes(Imf::Header& header, const FrameHeader& frame);

// Fills every field of `frame` except width, height and layers from the attributes.
// Fails with a CaptureError on a missing attribute, one of the wrong type or an invalid value.
void readFrameAttributes(const Imf::Header& header, const std::filesystem::path& file, FrameHeader& frame);

} // namespace glint::capture

#pragma once
// One entry point for "--input PATH" and the GUI's Open: picks the source from the path.
//   a folder with session.yml or frames/  -> SessionSource
//   a session.yml file                    -> SessionSource of its folder
//   a folder of images, or an image file  -> ImageGlobSource
//   a path whose file name has * ? [      -> ImageGlobSource (when no such file exists)
//   any other file                        -> VideoSource
// Anything else is an error that names the path and says what was expected.
#include "calib/source/FrameSource.h"

#include <string>

namespace omnitune {

SourceOpen<FrameSource> openFrameSource(const std::string& path);

}  // namespace omnitune

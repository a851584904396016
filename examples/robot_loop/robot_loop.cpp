// The robot's vision loop in miniature: load the config.yml the workbench saved, run the
// detector on every frame and print where the ball is. It links the installed omnitune_core
// and OpenCV only; frames come from a session folder or an image glob, read with cv::imread.
//   robot_loop CONFIG INPUT     INPUT: a session folder (its frames/*.png), a folder of PNGs,
//                               or a glob such as 'frames/*.png'
// Prints a CSV header, then one line per frame: frame,found,px,py,radius_px,x_m,y_m.
#include "core/ConfigParser.h"
#include "core/Pipeline.h"

#include <opencv2/core.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <vector>

namespace {

// The frame files INPUT names, in order (cv::glob sorts them).
std::vector<cv::String> framePaths(const std::string& input)
{
    std::string pattern = input;
    if (cv::utils::fs::isDirectory(input)) {
        const std::string frames = cv::utils::fs::join(input, "frames");
        pattern = cv::utils::fs::join(cv::utils::fs::isDirectory(frames) ? frames : input, "*.png");
    }
    std::vector<cv::String> paths;
    cv::glob(pattern, paths, false);
    return paths;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 3) {
        std::fprintf(stderr, "usage: robot_loop CONFIG INPUT\n");
        return 2;
    }
    const omnitune::ConfigLoad load = omnitune::loadConfig(argv[1]);
    if (!load.ok()) {
        std::fprintf(stderr, "robot_loop: %s\n", load.error->toString().c_str());
        return 1;
    }
    const std::vector<cv::String> paths = framePaths(argv[2]);
    if (paths.empty()) {
        std::fprintf(stderr, "robot_loop: %s: no frames (expected a session folder, a folder of PNGs or a glob)\n",
                     argv[2]);
        return 1;
    }

    std::unique_ptr<omnitune::Pipeline> made;
    try {
        made = std::make_unique<omnitune::Pipeline>(load.config);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "robot_loop: %s: %s\n", argv[1], e.what());
        return 1;
    }
    omnitune::Pipeline& pipeline = *made;
    omnitune::PipelineResult result;  // reused: a warm pipeline allocates nothing per frame
    std::printf("frame,found,px,py,radius_px,x_m,y_m\n");
    for (std::size_t i = 0; i < paths.size(); ++i) {
        const cv::Mat frame = cv::imread(paths[i], cv::IMREAD_COLOR);
        pipeline.process(frame, omnitune::PixelFormat::Bgr8, result);
        if (!result.ok()) {
            std::fprintf(stderr, "robot_loop: %s: %s\n", paths[i].c_str(), result.error.c_str());
            std::printf("%zu,0,,,,,\n", i);
            continue;
        }
        const omnitune::BallDetection& d = result.detection;
        if (d.found)
            std::printf("%zu,1,%.1f,%.1f,%.1f,%.3f,%.3f\n", i, d.px, d.py, d.radiusPx, d.xM, d.yM);
        else
            std::printf("%zu,0,,,,,\n", i);
    }
    return 0;
}

// Test helper, built with the fault hooks of core/AtomicFile.cpp (OMNITUNE_FAULT_INJECTION):
// `omnitune_save_victim CONFIG` loads CONFIG, changes a threshold and its mask image and saves
// both, as the window's Save does. OMNITUNE_FAULT_STOP / OMNITUNE_FAULT_FAIL interrupt the save.
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"

#include <opencv2/imgproc.hpp>

#include <iostream>

int main(int argc, char** argv)
{
    if (argc != 2) return 2;
    omnitune::ConfigLoad load = omnitune::loadConfig(argv[1]);
    if (!load.ok() || load.config.mask.empty()) {
        std::cerr << "error: " << (load.ok() ? std::string("the config has no mask") : load.error->toString()) << "\n";
        return 2;
    }
    load.config.edges.cannyLow += 1;
    cv::circle(load.config.mask, {load.config.mask.cols / 2, load.config.mask.rows / 2}, 20, cv::Scalar(0), cv::FILLED);
    if (const auto err = omnitune::saveConfig(load.config, argv[1])) {
        std::cerr << "error: " << err->toString() << "\n";
        return 1;
    }
    return 0;
}

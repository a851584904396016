// Test helper, built with the fault hooks of core/AtomicFile.cpp (OMNITUNE_FAULT_INJECTION):
// `omnitune_save_victim CONFIG` loads CONFIG, changes a threshold and the mask image and saves
// both. With the GUI built it goes the window's way (ConfigDocument: load, edit, Ctrl+S's
// save()); without, straight through saveConfig. OMNITUNE_FAULT_STOP / OMNITUNE_FAULT_FAIL
// interrupt the save.
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"
#ifdef OMNITUNE_VICTIM_WINDOW
#include "widgets/ConfigDocument.h"

#include <QCoreApplication>
#endif

#include <opencv2/imgproc.hpp>

#include <iostream>

namespace {

// The edit: one threshold up, a disc cut out of the mask.
omnitune::Config edited(omnitune::Config c)
{
    c.edges.cannyLow += 1;
    c.mask = c.mask.clone();
    cv::circle(c.mask, {c.mask.cols / 2, c.mask.rows / 2}, 20, cv::Scalar(0), cv::FILLED);
    return c;
}

int fail(const std::string& why)
{
    std::cerr << "error: " << why << "\n";
    return 1;
}

}  // namespace

int main(int argc, char** argv)
{
    if (argc != 2) return 2;
#ifdef OMNITUNE_VICTIM_WINDOW
    QCoreApplication app(argc, argv);
    omnitune::ConfigDocument doc;
    const QString path = QString::fromLocal8Bit(argv[1]);
    if (const auto err = doc.load(path)) return fail(err->toStdString());
    const omnitune::Config next = edited(doc.config());
    omnitune::Config withMask = doc.config();
    withMask.mask = next.mask;  // the mask as an editor would leave it (reset keeps the path)
    doc.reset(withMask, path);
    if (const auto err = doc.setValue("edges.canny_low", next.edges.cannyLow)) return fail(err->toStdString());
    if (const auto err = doc.save()) return fail(err->toStdString());
#else
    const omnitune::ConfigLoad load = omnitune::loadConfig(argv[1]);
    if (!load.ok()) return fail(load.error->toString());
    if (const auto err = omnitune::saveConfig(edited(load.config), argv[1])) return fail(err->toString());
#endif
    return 0;
}

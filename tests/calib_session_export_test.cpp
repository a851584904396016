// Save as session (issue 11), Qt-free: an image folder becomes a session folder whose frames
// read back pixel for pixel, with the config and an empty truth.csv; a cancel keeps a closed
// session of the frames written so far; a folder that is not empty is refused with the path
// named; a corrupt frame is left out and named, a config of another size is not written.
#include "CancelAfter.h"
#include "calib/session/SessionExport.h"
#include "calib/session/SessionReader.h"
#include "calib/source/FrameSourceFactory.h"
#include "calib/source/SessionSource.h"
#include "core/ConfigParser.h"

#include <opencv2/imgcodecs.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include <fstream>

using namespace omnitune;
using omnitune::testing::CancelAfter;

namespace {

// Distinct frames (a square moving along x) so a swapped or repeated frame shows.
cv::Mat frameImage(int i, cv::Size size)
{
    cv::Mat m(size, CV_8UC3, cv::Scalar(30, 90, 40));
    m(cv::Rect(10 + 7 * i, 20, 12, 12)).setTo(cv::Scalar(255, 128, 0 + 20 * i));
    return m;
}

std::string writeImageFolder(const QTemporaryDir& tmp, int count, cv::Size size)
{
    const std::string dir = tmp.filePath("images").toStdString();
    QDir().mkpath(QString::fromStdString(dir));
    for (int i = 0; i < count; ++i)
        cv::imwrite(dir + "/img_" + std::to_string(100 + i) + ".png", frameImage(i, size));
    return dir;
}


}  // namespace

class SessionExportTest : public QObject {
    Q_OBJECT
private slots:
    void imageFolderBecomesASession()
    {
        QTemporaryDir tmp;
        const cv::Size size(96, 80);  // any size: nothing assumes one
        auto opened = openFrameSource(writeImageFolder(tmp, 5, size));
        QVERIFY2(opened.ok(), opened.error.c_str());
        Config config;
        config.geometry.imageWidth = size.width;
        config.geometry.imageHeight = size.height;
        config.geometry.centerX = 48.5;
        config.geometry.centerY = 40;
        config.geometry.outerRadius = 38;
        config.geometry.innerRadius = 8;
        const std::string folder = tmp.filePath("out/s1").toStdString();
        Frame skipped;
        QVERIFY(!opened.source->read(3, skipped));  // a source not at its start still saves from frame 0
        const SessionExportResult r = exportSession(*opened.source, folder, config);
        QVERIFY2(r.ok(), r.error ? r.error->toString().c_str() : "");
        QCOMPARE(r.frames, 5);
        QVERIFY(!r.cancelled && r.skipped.empty());
        QVERIFY2(r.configNote.empty(), r.configNote.c_str());

        SessionOpen session = SessionReader::open(folder);
        QVERIFY(session.ok());
        QVERIFY(session.reader->warnings().empty());
        QCOMPARE(session.reader->frameCount(), 5);
        QCOMPARE(session.reader->info().width, size.width);
        QCOMPARE(session.reader->info().complete, std::optional<bool>(true));
        QVERIFY(session.reader->hasConfig());
        QVERIFY(session.reader->truth().empty());
        SessionSource source(*session.reader);
        for (int i = 0; i < 5; ++i) {
            Frame f;
            QVERIFY(!source.read(i, f));
            QCOMPARE(cv::norm(f.image, frameImage(i, size), cv::NORM_INF), 0.0);
        }
        const ConfigLoad load = loadConfig(session.reader->configPath());
        QVERIFY(load.ok());
        QCOMPARE(load.config.geometry.centerX, 48.5);
        std::ifstream truth(folder + "/truth.csv");
        std::string header;
        QVERIFY(std::getline(truth, header));
        QCOMPARE(header, truthCsvHeader());
        QVERIFY(!std::getline(truth, header));  // no rows yet
    }

    void cancelKeepsAClosedSession()
    {
        QTemporaryDir tmp;
        auto opened = openFrameSource(writeImageFolder(tmp, 6, {64, 64}));
        QVERIFY(opened.ok());
        CancelAfter cancel(2);
        const std::string folder = tmp.filePath("cut").toStdString();
        const SessionExportResult r = exportSession(*opened.source, folder, Config{}, {}, &cancel);
        QVERIFY(r.ok());
        QVERIFY(r.cancelled);
        QCOMPARE(r.frames, 2);
        SessionOpen session = SessionReader::open(folder);
        QVERIFY(session.ok());
        QCOMPARE(session.reader->frameCount(), 2);
        QCOMPARE(session.reader->info().complete, std::optional<bool>(true));
    }

    void refusals()
    {
        QTemporaryDir tmp;
        auto opened = openFrameSource(writeImageFolder(tmp, 2, {64, 64}));
        QVERIFY(opened.ok());
        // The image folder itself: not empty and not a session.
        const SessionExportResult intoSource = exportSession(*opened.source, tmp.filePath("images").toStdString(), Config{});
        QVERIFY(!intoSource.ok());
        QCOMPARE(intoSource.error->kind, SessionIssueKind::FolderNotEmpty);
        QVERIFY(QString::fromStdString(intoSource.error->toString()).contains("images"));

        // A corrupt frame among good ones is left out and named; a config for another size is
        // not written, and the result says so.
        const std::string mixed = tmp.filePath("mixed").toStdString();
        QDir().mkpath(QString::fromStdString(mixed));
        std::ofstream(mixed + "/a.png") << "not a png";
        cv::imwrite(mixed + "/b.png", frameImage(0, {64, 64}));
        cv::imwrite(mixed + "/c.png", frameImage(1, {64, 64}));
        auto mixedSource = openFrameSource(mixed);
        QVERIFY2(mixedSource.ok(), mixedSource.error.c_str());
        const std::string target = tmp.filePath("mixed-session").toStdString();
        const SessionExportResult r = exportSession(*mixedSource.source, target, Config{});  // Config{}: 640x480
        QVERIFY2(r.ok(), r.error ? r.error->toString().c_str() : "");
        QCOMPARE(r.frames, 2);
        QCOMPARE(int(r.skipped.size()), 1);
        QVERIFY2(QString::fromStdString(r.skipped.front()).contains("a.png"), r.skipped.front().c_str());
        QVERIFY2(QString::fromStdString(r.configNote).contains("640x480"), r.configNote.c_str());
        SessionOpen session = SessionReader::open(target);
        QVERIFY(session.ok());
        QVERIFY(!session.reader->hasConfig());
        QCOMPARE(session.reader->frameCount(), 2);
    }
};

QTEST_GUILESS_MAIN(SessionExportTest)
#include "calib_session_export_test.moc"

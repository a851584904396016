// Sessions against hostile or damaged input (issue 14): truth values no frame can hold, a
// session.yml naming a config outside its folder, a recording killed right after session.yml
// was rewritten, stray frame files numbered far past the others, and a simulated tour whose
// recording is cancelled. Each case names the defect it guards.
#include "CancelAfter.h"
#include "calib/session/Session.h"
#include "calib/session/SessionConfig.h"
#include "calib/session/SessionReader.h"
#include "calib/session/SessionWriter.h"
#include "calib/session/TruthCsv.h"
#include "calib/sim/TourRecording.h"

#include <opencv2/imgcodecs.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include "FileBytes.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace omnitune;
using omnitune::testing::CancelAfter;
namespace fs = std::filesystem;
using namespace filetest;

namespace {

const cv::Size kSize(64, 48);

cv::Mat frameOf(int index)
{
    cv::Mat m(kSize, CV_8UC3, cv::Scalar(index * 7 % 256, 40, 90));
    return m;
}

SessionInfo smallInfo()
{
    SessionInfo info;
    info.camera.model = "test";
    info.width = kSize.width;
    info.height = kSize.height;
    info.created = "2024-05-01T14:03:00Z";
    return info;
}

// A finished session of `frames` frames, every frame with a visible ball at (20, 20) r 5.
void recordSession(const std::string& folder, int frames)
{
    SessionCreate c = SessionWriter::create(folder, smallInfo());
    if (!c.ok()) qFatal("create failed: %s", c.error->toString().c_str());
    for (int i = 0; i < frames; ++i) {
        TruthRow t;
        t.ballVisible = true;
        t.px = 20;
        t.py = 20;
        t.radiusPx = 5;
        t.xM = 1;
        t.yM = 2;
        if (auto err = c.writer->appendFrame(frameOf(i), t)) qFatal("append failed: %s", err->toString().c_str());
    }
    if (auto err = c.writer->finish()) qFatal("finish failed: %s", err->toString().c_str());
}

std::string framePath(const std::string& folder, const std::string& name)
{
    return (fs::path(folder) / "frames" / name).string();
}

QString listed(const std::vector<SessionIssue>& warnings)
{
    QString s;
    for (const SessionIssue& w : warnings) s += QString::fromStdString(w.toString()) + "\n";
    return s;
}

bool mentions(const std::vector<SessionIssue>& warnings, const std::vector<std::string>& parts)
{
    return std::any_of(warnings.begin(), warnings.end(), [&](const SessionIssue& w) {
        const std::string text = w.toString();
        return std::all_of(parts.begin(), parts.end(),
                           [&](const std::string& p) { return text.find(p) != std::string::npos; });
    });
}

// Replaces (or adds) one top-level key of session.yml.
void setInfoKey(const std::string& folder, const std::string& key, const std::string& value)
{
    const std::string path = (fs::path(folder) / "session.yml").string();
    std::istringstream in(readFile(path));
    std::string out;
    bool found = false;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind(key + ":", 0) == 0) {
            line = key + ": " + value;
            found = true;
        }
        out += line + "\n";
    }
    if (!found) out += key + ": " + value + "\n";
    writeFile(path, out);
}


}  // namespace

class SessionRobustnessTest : public QObject {
    Q_OBJECT
private slots:
    // Defect 3: a truth row no frame can hold is refused with file, line and column; the rest loads.
    void truthOutsideTheFrameIsRefused_data()
    {
        QTest::addColumn<QString>("row");     // the bad row (frame 1), between two good ones
        QTest::addColumn<int>("width");       // the frame size the parser is told; 0: unknown (the window)
        QTest::addColumn<QString>("column");  // the column the warning names
        QTest::newRow("radius 1e30, size unknown") << "1,1,30,20,1e30,1,2" << 0 << "radius_px";
        QTest::newRow("radius 1e30") << "1,1,30,20,1e30,1,2" << 640 << "radius_px";
        QTest::newRow("radius larger than the frame") << "1,1,30,20,300,1,2" << 640 << "radius_px";
        QTest::newRow("centre left of the frame") << "1,1,-4,20,5,1,2" << 640 << "px";
        QTest::newRow("centre below the frame") << "1,1,30,480,5,1,2" << 640 << "py";
        QTest::newRow("px 1e30, size unknown") << "1,1,1e30,20,5,1,2" << 0 << "px";
        QTest::newRow("x_m 1e30") << "1,1,30,20,5,1e30,2" << 640 << "x_m";
        QTest::newRow("y_m -1e300") << "1,1,30,20,5,1,-1e300" << 640 << "y_m";
    }

    void truthOutsideTheFrameIsRefused()
    {
        QFETCH(QString, row);
        QFETCH(int, width);
        QFETCH(QString, column);
        const std::string text = "frame,ball_visible,px,py,radius_px,x_m,y_m\n0,1,30,20,5,1,2\n" + row.toStdString() +
                                 "\n2,1,31,21,5.5,1.1,2.1\n";
        TruthLimits limits;
        if (width > 0) limits.frameSize = {width, 480};
        const TruthParse p = parseTruthCsv(text, "s/truth.csv", limits);
        QVERIFY(p.ok());
        QCOMPARE(p.dataRows, 3);
        QCOMPARE(int(p.rows.size()), 2);
        QVERIFY(p.rows.count(0) && p.rows.count(2));
        QVERIFY2(!p.rows.count(1), "the impossible row was loaded");
        QCOMPARE(int(p.warnings.size()), 1);
        const SessionIssue& w = p.warnings.front();
        QCOMPARE(w.kind, SessionIssueKind::BadValue);
        QCOMPARE(w.line, 3);
        QCOMPARE(QString::fromStdString(w.key), column);
        QVERIFY2(w.toString().rfind("s/truth.csv:3: " + column.toStdString() + ": ", 0) == 0, w.toString().c_str());
        QVERIFY2(w.message.find("row skipped") != std::string::npos, w.message.c_str());
    }

    // Defect 3 through the reader: the session's frame size bounds its truth.
    void readerBoundsTruthByTheFrameSize()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        recordSession(folder, 3);
        writeFile(folder + "/truth.csv",
                  "frame,ball_visible,px,py,radius_px,x_m,y_m\n0,1,20,20,5,1,2\n1,1,70,20,5,1,2\n2,1,20,20,1e30,1,2\n");
        const SessionOpen opened = SessionReader::open(folder);
        QVERIFY(opened.ok());
        const SessionReader& r = *opened.reader;
        QCOMPARE(int(r.truth().size()), 1);  // 70 is outside the 64 px wide frames
        QVERIFY2(mentions(r.warnings(), {"truth.csv:3: px: 70 is outside the 64x48 frame"}), qPrintable(listed(r.warnings())));
        QVERIFY2(mentions(r.warnings(), {"truth.csv:4: radius_px: 1e+30 px does not fit"}),
                 qPrintable(listed(r.warnings())));
        QVERIFY(r.hasTruthFile());
        QCOMPARE(r.truthRowsInFile(), 3);
    }

    // Defect 6: one rule for the config a session names; only files inside its folder.
    void sessionConfigRule_data()
    {
        QTest::addColumn<QString>("configFile");  // session.yml's config_file; "" leaves it out
        QTest::addColumn<QString>("expected");    // the file used, relative to the session; "" none
        QTest::addColumn<QString>("reason");      // a word of the issue when refused
        QTest::newRow("named, inside") << "tuned.yml" << "tuned.yml" << "";
        QTest::newRow("named, in a subfolder") << "cfg/robot3.yml" << "cfg/robot3.yml" << "";
        QTest::newRow("not named: config.yml") << "" << "config.yml" << "";
        QTest::newRow("absolute /etc/passwd") << "/etc/passwd" << "" << "absolute";
        QTest::newRow("parent folder") << "../outside.yml" << "" << "leaves";
        QTest::newRow("up and back in") << "cfg/../tuned.yml" << "" << "leaves";
        QTest::newRow("a link out of the folder") << "link.yml" << "" << "outside";
        QTest::newRow("missing") << "gone.yml" << "" << "not in the session folder";
        QTest::newRow("a folder") << "cfg" << "" << "not a regular file";
    }

    void sessionConfigRule()
    {
        QFETCH(QString, configFile);
        QFETCH(QString, expected);
        QFETCH(QString, reason);
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        recordSession(folder, 2);
        for (const char* name : {"config.yml", "tuned.yml", "cfg/robot3.yml"}) {
            fs::create_directories(fs::path(folder) / "cfg");
            writeFile(folder + "/" + name, "config\n");
        }
        writeFile(tmp.filePath("outside.yml").toStdString(), "outside\n");
        fs::create_symlink(tmp.filePath("outside.yml").toStdString(), folder + "/link.yml");
        if (!configFile.isEmpty()) setInfoKey(folder, "config_file", "\"" + configFile.toStdString() + "\"");

        const SessionConfigChoice choice = sessionConfigPath(folder, configFile.toStdString(), "s/session.yml");
        const SessionOpen opened = SessionReader::open(folder);
        QVERIFY(opened.ok());
        const std::string want = expected.isEmpty() ? std::string() : (fs::path(folder) / expected.toStdString()).string();
        QCOMPARE(choice.path, want);
        QCOMPARE(opened.reader->configPath(), want);  // the reader (and so the window) follows the rule
        if (reason.isEmpty()) {
            QVERIFY2(!choice.issue, choice.issue ? choice.issue->toString().c_str() : "");
            return;
        }
        QVERIFY(choice.issue);
        const std::string text = choice.issue->toString();
        QVERIFY2(text.find("config_file") != std::string::npos && text.find(configFile.toStdString()) != std::string::npos &&
                     text.find(reason.toStdString()) != std::string::npos,
                 text.c_str());
        QVERIFY(opened.reader->configIssue());
        QVERIFY2(mentions(opened.reader->warnings(), {"config_file", reason.toStdString()}),
                 qPrintable(listed(opened.reader->warnings())));
    }

    // config.yml itself may not lead out of the session either (the same rule as config_file).
    void configYmlLinkingOutIsRefused()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        recordSession(folder, 2);
        fs::remove(fs::path(folder) / "config.yml");
        writeFile(tmp.filePath("outside.yml").toStdString(), "outside\n");
        fs::create_symlink(tmp.filePath("outside.yml").toStdString(), folder + "/config.yml");
        const SessionConfigChoice choice = sessionConfigPath(folder, "", "s/session.yml");
        QCOMPARE(choice.path, std::string());
        QVERIFY(choice.issue);
        QVERIFY2(choice.issue->toString().find("outside the session folder") != std::string::npos,
                 choice.issue->toString().c_str());
    }

    // Defect 7: killed right after the periodic session.yml rewrite, a recording used to look
    // complete (frame_count matched frames/). The folder is copied at that moment: what a kill
    // leaves on disk.
    void recordingKilledAfterTheRewriteIsReportedInterrupted()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("rec").toStdString();
        const std::string killed = tmp.filePath("killed").toStdString();
        SessionWriterOptions options;
        options.infoEveryFrames = 4;
        SessionCreate c = SessionWriter::create(folder, smallInfo(), options);
        QVERIFY(c.ok());
        for (int i = 0; i < 8; ++i) QVERIFY(!c.writer->appendFrame(frameOf(i)));
        QVERIFY(readFile(folder + "/session.yml").find("frame_count: 8") != std::string::npos);
        fs::copy(folder, killed, fs::copy_options::recursive);

        const SessionOpen interrupted = SessionReader::open(killed);
        QVERIFY(interrupted.ok());
        QCOMPARE(interrupted.reader->frameCount(), 8);
        QVERIFY2(mentions(interrupted.reader->warnings(), {"session.yml", "complete", "interrupted"}),
                 qPrintable("a killed recording reads as complete:\n" + listed(interrupted.reader->warnings())));

        QVERIFY(!c.writer->finish());
        QVERIFY(readFile(folder + "/session.yml").find("complete: true") != std::string::npos);
        const SessionOpen closed = SessionReader::open(folder);
        QVERIFY(closed.ok());
        QVERIFY2(closed.reader->warnings().empty(), qPrintable(listed(closed.reader->warnings())));
    }

    // Defect 7, the parser: complete is optional (older files), but must be true or false.
    void completeKeyParses()
    {
        SessionInfo info = smallInfo();
        info.complete = false;
        const SessionInfoParse p = parseSessionInfo(serializeSessionInfo(info), "session.yml");
        QVERIFY(p.ok() && p.warnings.empty());
        QCOMPARE(p.info.complete, std::optional<bool>(false));
        info.complete.reset();
        QVERIFY(!parseSessionInfo(serializeSessionInfo(info), "session.yml").info.complete.has_value());
        std::string text = serializeSessionInfo(info) + "complete: maybe\n";
        const SessionInfoParse bad = parseSessionInfo(text, "session.yml");
        QVERIFY2(mentions(bad.warnings, {"complete", "true or false"}), qPrintable(listed(bad.warnings)));
    }

    // Defect 10: a stray frame file numbered far past the others is not a billion-frame session,
    // and names past the six-digit limit are never counted.
    void strayFramesAreNotCounted_data()
    {
        QTest::addColumn<QString>("stray");
        QTest::addColumn<bool>("withInfo");  // session.yml kept; without it the frames alone count
        QTest::addColumn<QString>("reason");
        QTest::newRow("999999999.png") << "999999999.png" << true << "limit";
        QTest::newRow("1000000.png, just past the limit") << "1000000.png" << true << "limit";
        QTest::newRow("999999.png, within the limit") << "999999.png" << true << "stray";
        QTest::newRow("000050.png after a gap") << "000050.png" << true << "stray";
        QTest::newRow("999999.png, no session.yml") << "999999.png" << false << "stray";
    }

    void strayFramesAreNotCounted()
    {
        QFETCH(QString, stray);
        QFETCH(bool, withInfo);
        QFETCH(QString, reason);
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        recordSession(folder, 5);
        fs::copy_file(framePath(folder, "000001.png"), framePath(folder, stray.toStdString()));
        if (!withInfo) fs::remove(folder + "/session.yml");
        const SessionOpen opened = SessionReader::open(folder);
        QVERIFY(opened.ok());
        QCOMPARE(opened.reader->frameCount(), 5);
        QVERIFY2(mentions(opened.reader->warnings(), {stray.toStdString(), reason.toStdString(), "ignored"}),
                 qPrintable(listed(opened.reader->warnings())));
        cv::Mat image;
        QVERIFY(!opened.reader->readFrame(4, image));
    }

    // A hole in a recorded session stays a hole (the frames after it still count).
    void holesBelowTheCountStay()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        recordSession(folder, 6);
        fs::remove(framePath(folder, "000002.png"));
        const SessionOpen opened = SessionReader::open(folder);
        QVERIFY(opened.ok());
        QCOMPARE(opened.reader->frameCount(), 6);
    }

    // Issue 13: tour recording lives in calib/sim and honours the progress interface's cancel.
    void tourRecordingStopsWhenCancelled()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("tour").toStdString();
        TourRecordingOptions options;
        options.tour.frames = 6;
        CancelAfter cancel(2);
        const TourRecordingResult result = recordTour(folder, Config{}, options, &cancel);
        QVERIFY2(result.ok(), result.error ? result.error->toString().c_str() : "");
        QVERIFY(result.cancelled);
        QCOMPARE(result.frames, 2);
        const SessionOpen opened = SessionReader::open(folder);
        QVERIFY(opened.ok());
        QCOMPARE(opened.reader->frameCount(), 2);
        QCOMPARE(int(opened.reader->truth().size()), 2);
        QVERIFY(opened.reader->hasConfig());
        QCOMPARE(opened.reader->info().complete, std::optional<bool>(true));
        QVERIFY2(opened.reader->info().notes.find("6 frames") != std::string::npos, opened.reader->info().notes.c_str());
        QVERIFY2(opened.reader->warnings().empty(), qPrintable(listed(opened.reader->warnings())));
    }
};

QTEST_GUILESS_MAIN(SessionRobustnessTest)
#include "calib_session_robustness_test.moc"

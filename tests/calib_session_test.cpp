// Recorded sessions and frame sources: bit-exact round trips in random order, the session.yml
// and truth.csv parsers' typed warnings, interrupted recordings, and picking a source by path.
#include "calib/source/FrameSourceFactory.h"
#include "calib/source/ImageGlobSource.h"
#include "calib/session/Session.h"
#include "calib/session/SessionReader.h"
#include "calib/source/SessionSource.h"
#include "calib/session/SessionWriter.h"
#include "calib/session/TruthCsv.h"
#include "calib/source/VideoSource.h"

#include "core/ConfigParser.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>

#include <QTemporaryDir>
#include <QtTest>

#include "FileBytes.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

using namespace omnitune;
namespace fs = std::filesystem;
using namespace filetest;
Q_DECLARE_METATYPE(omnitune::SessionIssueKind)
Q_DECLARE_METATYPE(omnitune::FrameErrorKind)

namespace {

const cv::Size kSize(64, 48);

// A frame no other index produces: seeded noise plus the index drawn large.
cv::Mat syntheticFrame(int index, cv::Size size = kSize)
{
    cv::Mat m(size, CV_8UC3);
    cv::RNG rng(0x5e55 + index);
    rng.fill(m, cv::RNG::UNIFORM, 0, 256);
    cv::putText(m, std::to_string(index), {4, size.height - 8}, cv::FONT_HERSHEY_SIMPLEX, 1.0, {255, 255, 255}, 2);
    return m;
}

bool identical(const cv::Mat& a, const cv::Mat& b)
{
    return a.size() == b.size() && a.type() == b.type() && cv::norm(a, b, cv::NORM_INF) == 0.0;
}

SessionInfo exampleInfo()
{
    SessionInfo info;
    info.camera.model = "PointGrey Flea2 (robot 3)";
    info.camera.frameRate = 15.0;
    info.camera.exposure = 412;
    info.camera.whiteBalanceBlue = 610;
    info.camera.whiteBalanceRed = 388;
    info.camera.gain = 17;
    info.camera.brightness = 90;
    info.width = kSize.width;
    info.height = kSize.height;
    info.pixelFormat = PixelFormat::Uyvy;
    info.frameRate = 14.985;
    info.notes = "ball rolled from the goal line\n\"second\" try: # not a comment";
    info.created = "2024-05-01T14:03:00Z";
    return info;
}

TruthRow truthFor(int frame)
{
    TruthRow t;
    t.frame = frame;
    t.ballVisible = frame % 3 != 2;
    if (t.ballVisible) {
        t.px = 10.5 + frame;
        t.py = 20.25;
        t.radiusPx = 3.0 + 0.1 * frame;
        t.xM = -1.7 + 0.3 * frame;
        t.yM = 2.0 / 3.0;
    }
    if (frame % 2 == 0) t.robot = RobotPose{1.25, -3.5, 0.1 * frame};
    return t;
}

bool sameTruth(const TruthRow& a, const TruthRow& b)
{
    const bool samePose = a.robot.has_value() == b.robot.has_value() &&
                          (!a.robot || (a.robot->x == b.robot->x && a.robot->y == b.robot->y &&
                                        a.robot->heading == b.robot->heading));
    return a.frame == b.frame && a.ballVisible == b.ballVisible && a.px == b.px && a.py == b.py &&
           a.radiusPx == b.radiusPx && a.xM == b.xM && a.yM == b.yM && samePose;
}

bool hasWarning(const std::vector<SessionIssue>& warnings, SessionIssueKind kind, const std::string& mentions = {})
{
    return std::any_of(warnings.begin(), warnings.end(), [&](const SessionIssue& w) {
        return w.kind == kind && w.toString().find(mentions) != std::string::npos;
    });
}

QString listed(const std::vector<SessionIssue>& warnings)
{
    QString s;
    for (const SessionIssue& w : warnings) s += QString::fromStdString(w.toString()) + "\n";
    return s;
}

// Records `frames` frames with truth on every frame; returns the writer still open.
SessionWriter record(const std::string& folder, int frames, SessionWriterOptions options = {})
{
    SessionCreate created = SessionWriter::create(folder, exampleInfo(), options);
    if (!created.ok()) qFatal("create failed: %s", created.error->toString().c_str());
    for (int i = 0; i < frames; ++i)
        if (auto err = created.writer->appendFrame(syntheticFrame(i), truthFor(i)))
            qFatal("append failed: %s", err->toString().c_str());
    return std::move(*created.writer);
}

std::string framePath(const std::string& folder, int index)
{
    return (fs::path(folder) / "frames" / sessionFrameName(index)).string();
}

std::string pngBytes(const cv::Mat& image)
{
    std::vector<std::uint8_t> buf;
    cv::imencode(".png", image, buf);
    return std::string(buf.begin(), buf.end());
}

}  // namespace

class SessionTest : public QObject {
    Q_OBJECT
private slots:
    void framesRoundTripBitExactInRandomOrder()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("run1").toStdString();
        const int n = 9;
        {
            SessionWriter w = record(folder, n);
            QVERIFY(!w.writeConfig(Config{}));
            QVERIFY(!w.finish());
        }
        SessionOpen opened = SessionReader::open(folder);
        QVERIFY2(opened.ok(), opened.error ? opened.error->toString().c_str() : "");
        const SessionReader& r = *opened.reader;
        QVERIFY2(r.warnings().empty(), qPrintable(listed(r.warnings())));
        QVERIFY(r.hasInfoFile());
        QCOMPARE(r.frameCount(), n);
        QCOMPARE(r.frameSize(), kSize);

        const SessionInfo want = exampleInfo();
        const SessionInfo& got = r.info();
        QCOMPARE(got.camera.model, want.camera.model);
        QCOMPARE(got.camera.frameRate, want.camera.frameRate);
        QCOMPARE(got.camera.exposure, want.camera.exposure);
        QCOMPARE(got.camera.whiteBalanceBlue, want.camera.whiteBalanceBlue);
        QCOMPARE(got.camera.whiteBalanceRed, want.camera.whiteBalanceRed);
        QCOMPARE(got.camera.gain, want.camera.gain);
        QCOMPARE(got.camera.brightness, want.camera.brightness);
        QCOMPARE(got.pixelFormat, PixelFormat::Uyvy);
        QCOMPARE(got.frameRate, want.frameRate);
        QCOMPARE(got.notes, want.notes);
        QCOMPARE(got.created, want.created);

        std::vector<int> order(n);
        for (int i = 0; i < n; ++i) order[std::size_t(i)] = i;
        std::shuffle(order.begin(), order.end(), std::mt19937(7));
        order.push_back(order.front());  // and back to one already read
        for (int i : order) {
            cv::Mat image;
            const auto err = r.readFrame(i, image);
            QVERIFY2(!err, err ? err->message.c_str() : "");
            QVERIFY2(identical(image, syntheticFrame(i)), qPrintable(QString("frame %1 differs").arg(i)));
        }
        QVERIFY(!identical(syntheticFrame(0), syntheticFrame(1)));  // the check above can tell frames apart

        QCOMPARE(int(r.truth().size()), n);
        for (int i = 0; i < n; ++i) {
            QVERIFY(r.truthFor(i));
            QVERIFY2(sameTruth(*r.truthFor(i), truthFor(i)), qPrintable(QString("truth of frame %1").arg(i)));
        }

        QVERIFY(r.hasConfig());
        QCOMPARE(fs::path(r.configPath()).filename().string(), std::string("config.yml"));
        QVERIFY(loadConfig(r.configPath()).ok());
    }

    void sessionSourceSeeksAndPlaysOn()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        record(folder, 5).finish();
        SessionOpen opened = SessionReader::open(folder);
        QVERIFY(opened.ok());
        SessionSource source(std::move(*opened.reader));
        QVERIFY(source.isSeekable());
        QCOMPARE(source.frameCount(), 5);

        Frame f;
        QVERIFY(!source.read(3, f));
        QCOMPARE(f.index, 3);
        QVERIFY(identical(f.image, syntheticFrame(3)));
        QCOMPARE(f.timestampS, 3 / exampleInfo().frameRate);
        QVERIFY(f.camera.has_value());
        QCOMPARE(f.camera->exposure, exampleInfo().camera.exposure);

        QVERIFY(!source.read(FrameSource::kNext, f));  // the one after the last asked for
        QCOMPARE(f.index, 4);
        QVERIFY(identical(f.image, syntheticFrame(4)));
        const auto end = source.read(FrameSource::kNext, f);
        QVERIFY(end);
        QCOMPARE(end->kind, FrameErrorKind::OutOfRange);
        const auto negative = source.read(-7, f);
        QVERIFY(negative);
        QCOMPARE(negative->kind, FrameErrorKind::OutOfRange);
        QVERIFY(!source.read(0, f));
        QVERIFY(identical(f.image, syntheticFrame(0)));
    }

    void writerRewritesSessionYmlEveryNFrames()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        SessionWriterOptions options;
        options.infoEveryFrames = 2;
        SessionWriter w = record(folder, 5, options);
        const std::string infoPath = (fs::path(folder) / "session.yml").string();
        SessionInfoParse mid = parseSessionInfo(readFile(infoPath), infoPath);
        QVERIFY(mid.ok());
        QCOMPARE(mid.info.frameCount, 4);  // rewritten after frames 2 and 4, not yet after 5
        QVERIFY(!w.finish());
        SessionInfoParse done = parseSessionInfo(readFile(infoPath), infoPath);
        QCOMPARE(done.info.frameCount, 5);
        QVERIFY(w.appendFrame(syntheticFrame(5)));  // refused after finish
        QVERIFY(!fs::exists(framePath(folder, 5)));
    }

    void writerRefusesWrongFrames()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        SessionCreate created = SessionWriter::create(folder, exampleInfo());
        QVERIFY(created.ok());
        SessionWriter& w = *created.writer;

        const auto wrongSize = w.appendFrame(syntheticFrame(0, {32, 24}));
        QVERIFY(wrongSize);
        QCOMPARE(wrongSize->kind, SessionIssueKind::WrongFrame);
        QVERIFY2(wrongSize->message.find("32x24") != std::string::npos &&
                     wrongSize->message.find("64x48") != std::string::npos,
                 wrongSize->message.c_str());
        const auto gray = w.appendFrame(cv::Mat(kSize, CV_8UC1, cv::Scalar(9)));
        QVERIFY(gray);
        QCOMPARE(gray->kind, SessionIssueKind::WrongFrame);
        QVERIFY2(gray->message.find("CV_8UC1") != std::string::npos, gray->message.c_str());
        QCOMPARE(w.frameCount(), 0);
        QVERIFY(!fs::exists(framePath(folder, 0)));

        QVERIFY(!w.appendFrame(syntheticFrame(0)));
        QCOMPARE(w.frameCount(), 1);
        QVERIFY(fs::exists(framePath(folder, 0)));
    }

    void writerRefusesSettingsOutOfRange()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        SessionInfo info = exampleInfo();
        info.camera.gain = 5000;
        const SessionCreate refused = SessionWriter::create(folder, info);
        QVERIFY(!refused.ok());
        QCOMPARE(refused.error->kind, SessionIssueKind::OutOfRange);
        QCOMPARE(refused.error->key, std::string("camera.gain"));
        QVERIFY2(refused.error->message.find("5000") != std::string::npos, refused.error->message.c_str());
        QVERIFY(!fs::exists(folder));  // checked before anything is written
        info = exampleInfo();
        info.frameRate = 0.0;
        QVERIFY(!SessionWriter::create(folder, info).ok());
    }

    void writerTakesTheSizeFromTheFirstFrameWhenNotGiven()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        SessionInfo info;
        SessionCreate created = SessionWriter::create(folder, info);
        QVERIFY(created.ok());
        QVERIFY(!created.writer->appendFrame(syntheticFrame(0, {505, 480})));
        QVERIFY(created.writer->appendFrame(syntheticFrame(1)));  // 64x48 no longer fits
        QVERIFY(!created.writer->finish());
        SessionOpen opened = SessionReader::open(folder);
        QVERIFY(opened.ok());
        QCOMPARE(opened.reader->frameSize(), cv::Size(505, 480));
        QCOMPARE(opened.reader->frameCount(), 1);
    }

    void writerWillNotOverwriteUnlessAsked()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        record(folder, 3).finish();

        SessionCreate again = SessionWriter::create(folder, exampleInfo());
        QVERIFY(!again.ok());
        QCOMPARE(again.error->kind, SessionIssueKind::FolderNotEmpty);
        QVERIFY(fs::exists(framePath(folder, 2)));

        SessionWriterOptions overwrite;
        overwrite.overwrite = true;
        SessionCreate replaced = SessionWriter::create(folder, exampleInfo(), overwrite);
        QVERIFY(replaced.ok());
        QVERIFY(!replaced.writer->finish());
        QVERIFY(!fs::exists(framePath(folder, 0)));
        QVERIFY(!fs::exists(fs::path(folder) / "truth.csv"));
        QCOMPARE(SessionReader::open(folder).reader->frameCount(), 0);

        // A folder that is not a session is never emptied.
        const std::string other = tmp.filePath("documents").toStdString();
        fs::create_directories(other);
        writeFile(other + "/thesis.tex", "keep me");
        SessionCreate refused = SessionWriter::create(other, exampleInfo(), overwrite);
        QVERIFY(!refused.ok());
        QCOMPARE(refused.error->kind, SessionIssueKind::FolderNotEmpty);
        QCOMPARE(readFile(other + "/thesis.tex"), std::string("keep me"));
    }

    void interruptedRecordingStillOpens_data()
    {
        QTest::addColumn<QString>("damage");
        QTest::addColumn<int>("expectedFrames");
        QTest::addColumn<SessionIssueKind>("expectedWarning");
        QTest::newRow("session.yml deleted") << "delete-info" << 5 << SessionIssueKind::MissingInfo;
        QTest::newRow("session.yml stale (as at the crash)") << "stale-info" << 5 << SessionIssueKind::FrameCountMismatch;
        QTest::newRow("last PNG cut short") << "truncated-png" << 5 << SessionIssueKind::TruncatedFrame;
        QTest::newRow("last PNG empty") << "empty-png" << 5 << SessionIssueKind::TruncatedFrame;
        QTest::newRow("stale, no yml and cut PNG at once") << "all" << 5 << SessionIssueKind::MissingInfo;
    }

    void interruptedRecordingStillOpens()
    {
        QFETCH(QString, damage);
        QFETCH(int, expectedFrames);
        QFETCH(SessionIssueKind, expectedWarning);
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("crashed").toStdString();
        const std::string infoPath = (fs::path(folder) / "session.yml").string();
        SessionWriterOptions options;
        options.infoEveryFrames = 100;  // session.yml still says 0 frames at the "crash"
        std::string atCrash;
        {
            SessionWriter w = record(folder, 5, options);
            atCrash = readFile(infoPath);
        }  // destroyed without finish(); what the disk held at the crash is restored below
        QVERIFY(atCrash.find("frame_count: 0") != std::string::npos);
        const std::string half = pngBytes(syntheticFrame(5));
        if (damage == "delete-info" || damage == "all") fs::remove(infoPath);
        if (damage == "stale-info") writeFile(infoPath, atCrash);
        if (damage == "truncated-png" || damage == "all") writeFile(framePath(folder, 5), half.substr(0, half.size() / 2));
        if (damage == "empty-png") writeFile(framePath(folder, 5), "");

        SessionOpen opened = SessionReader::open(folder);
        QVERIFY2(opened.ok(), opened.error ? opened.error->toString().c_str() : "");
        const SessionReader& r = *opened.reader;
        QCOMPARE(r.frameCount(), expectedFrames);
        QCOMPARE(r.frameSize(), kSize);
        QVERIFY2(hasWarning(r.warnings(), expectedWarning), qPrintable(listed(r.warnings())));
        if (damage != "stale-info" && damage != "delete-info")
            QVERIFY2(hasWarning(r.warnings(), SessionIssueKind::TruncatedFrame, sessionFrameName(5)),
                     qPrintable(listed(r.warnings())));
        for (int i = expectedFrames - 1; i >= 0; --i) {
            cv::Mat image;
            QVERIFY(!r.readFrame(i, image));
            QVERIFY(identical(image, syntheticFrame(i)));
            QVERIFY(r.truthFor(i) && sameTruth(*r.truthFor(i), truthFor(i)));
        }
        cv::Mat image;
        const auto beyond = r.readFrame(expectedFrames, image);
        QVERIFY(beyond);
        QCOMPARE(beyond->kind, FrameErrorKind::OutOfRange);
    }

    void badFramesAreErrorsNamingTheFile_data()
    {
        QTest::addColumn<QString>("damage");
        QTest::addColumn<FrameErrorKind>("kind");
        QTest::newRow("missing") << "missing" << FrameErrorKind::Missing;
        QTest::newRow("not a PNG") << "garbage" << FrameErrorKind::Unreadable;
        QTest::newRow("wrong size") << "small" << FrameErrorKind::WrongSize;
    }

    void badFramesAreErrorsNamingTheFile()
    {
        QFETCH(QString, damage);
        QFETCH(FrameErrorKind, kind);
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        record(folder, 5).finish();
        const std::string victim = framePath(folder, 2);
        if (damage == "missing") fs::remove(victim);
        if (damage == "garbage") writeFile(victim, "this is not a PNG at all");
        if (damage == "small") writeFile(victim, pngBytes(syntheticFrame(2, {32, 24})));

        SessionOpen opened = SessionReader::open(folder);
        QVERIFY(opened.ok());
        QCOMPARE(opened.reader->frameCount(), 5);  // a hole in the middle is not the end
        if (damage == "missing")
            QVERIFY2(hasWarning(opened.reader->warnings(), SessionIssueKind::MissingFrames, "000002.png"),
                     qPrintable(listed(opened.reader->warnings())));
        SessionSource source(std::move(*opened.reader));
        Frame f;
        std::vector<int> delivered;
        std::optional<FrameError> bad;
        for (int guard = 0; guard < 10; ++guard) {
            const auto err = source.read(FrameSource::kNext, f);
            if (err && err->kind == FrameErrorKind::OutOfRange) break;
            if (err) {
                bad = err;
                continue;
            }
            QVERIFY(identical(f.image, syntheticFrame(f.index)));
            delivered.push_back(f.index);
        }
        QCOMPARE(delivered, (std::vector<int>{0, 1, 3, 4}));  // played past the bad one
        QVERIFY(bad);
        QCOMPARE(bad->kind, kind);
        QCOMPARE(bad->index, 2);
        QCOMPARE(bad->file, victim);
        QVERIFY2(bad->message.find(victim) != std::string::npos, bad->message.c_str());
    }

    void notASessionIsAClearError_data()
    {
        QTest::addColumn<QString>("layout");
        QTest::addColumn<SessionIssueKind>("kind");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("no such folder") << "none" << SessionIssueKind::FileUnreadable << "no such folder";
        QTest::newRow("empty folder") << "empty" << SessionIssueKind::NotASession << "neither session.yml nor frames/";
        QTest::newRow("a config, not a session") << "config" << SessionIssueKind::NotASession << "session_format";
        QTest::newRow("a future format") << "future" << SessionIssueKind::UnknownFormat << "session_format 2";
    }

    void notASessionIsAClearError()
    {
        QFETCH(QString, layout);
        QFETCH(SessionIssueKind, kind);
        QFETCH(QString, mentions);
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        if (layout != "none") fs::create_directories(folder);
        if (layout == "config") writeFile(folder + "/session.yml", "schema: 1\nhough:\n  canny_low: 60\n");
        if (layout == "future") writeFile(folder + "/session.yml", "session_format: 2\nframe_count: 3\n");
        const SessionOpen opened = SessionReader::open(folder);
        QVERIFY(!opened.ok());
        QCOMPARE(opened.error->kind, kind);
        const std::string text = opened.error->toString();
        QVERIFY2(text.find(mentions.toStdString()) != std::string::npos, text.c_str());
        QVERIFY2(text.find(folder) != std::string::npos, text.c_str());  // names the file
    }

    void sessionInfoRoundTrip()
    {
        SessionInfo info = exampleInfo();
        info.configFile = "tuned.yml";
        info.frameCount = 1234;
        const SessionInfoParse p = parseSessionInfo(serializeSessionInfo(info), "session.yml");
        QVERIFY(p.ok());
        QVERIFY2(p.warnings.empty(), qPrintable(listed(p.warnings)));
        QCOMPARE(p.info.frameCount, 1234);
        QCOMPARE(p.info.width, info.width);
        QCOMPARE(p.info.height, info.height);
        QCOMPARE(p.info.frameRate, info.frameRate);
        QCOMPARE(p.info.camera.model, info.camera.model);
        QCOMPARE(p.info.camera.whiteBalanceRed, info.camera.whiteBalanceRed);
        QCOMPARE(p.info.notes, info.notes);
        QCOMPARE(p.info.configFile, std::string("tuned.yml"));
        QCOMPARE(p.info.pixelFormat, PixelFormat::Uyvy);
        QVERIFY(QRegularExpression("^\\d{4}-\\d\\d-\\d\\dT\\d\\d:\\d\\d:\\d\\dZ$")
                    .match(QString::fromStdString(isoUtcNow()))
                    .hasMatch());
    }

    void sessionInfoWarnings_data()
    {
        QTest::addColumn<QString>("linePrefix");   // the line of a good file to change; empty: add a line
        QTest::addColumn<QString>("replacement");  // empty: delete the line
        QTest::addColumn<SessionIssueKind>("kind");
        QTest::addColumn<QString>("key");
        QTest::addColumn<bool>("knowsLine");
        QTest::newRow("missing frame_rate") << "frame_rate:" << "" << SessionIssueKind::MissingKey << "frame_rate" << false;
        QTest::newRow("missing camera.gain") << "   gain:" << "" << SessionIssueKind::MissingKey << "camera.gain" << false;
        QTest::newRow("typo'd key") << "" << "frame_cout: 3" << SessionIssueKind::UnknownKey << "frame_cout" << true;
        QTest::newRow("typo'd camera key") << "   gain:" << "   gian: 17" << SessionIssueKind::UnknownKey << "camera.gian" << true;
        QTest::newRow("text for a count") << "frame_count:" << "frame_count: lots" << SessionIssueKind::WrongType
                                          << "frame_count" << true;
        QTest::newRow("gain out of range") << "   gain:" << "   gain: 5000" << SessionIssueKind::OutOfRange << "camera.gain" << true;
        QTest::newRow("negative width") << "frame_width:" << "frame_width: -4" << SessionIssueKind::OutOfRange
                                        << "frame_width" << true;
        QTest::newRow("unknown pixel format") << "pixel_format:" << "pixel_format: rgb565" << SessionIssueKind::WrongType
                                              << "pixel_format" << true;
        QTest::newRow("camera rate above the schema's") << "   frame_rate:" << "   frame_rate: 500" << SessionIssueKind::OutOfRange
                                                       << "camera.frame_rate" << true;
        QTest::newRow("zero frame rate") << "frame_rate:" << "frame_rate: 0" << SessionIssueKind::OutOfRange << "frame_rate" << true;
    }

    void sessionInfoWarnings()
    {
        QFETCH(QString, linePrefix);
        QFETCH(QString, replacement);
        QFETCH(SessionIssueKind, kind);
        QFETCH(QString, key);
        QFETCH(bool, knowsLine);
        const std::string good = serializeSessionInfo(exampleInfo());
        const std::string prefix = linePrefix.toStdString(), repl = replacement.toStdString();
        std::istringstream in(good);
        std::string text;
        int lineNo = 0, editedLine = 0;
        for (std::string line; std::getline(in, line);) {
            ++lineNo;
            if (!prefix.empty() && !editedLine && line.rfind(prefix, 0) == 0) {
                editedLine = lineNo;
                if (!repl.empty()) text += repl + "\n";
                continue;
            }
            text += line + "\n";
        }
        if (prefix.empty()) {
            text += repl + "\n";
            editedLine = lineNo + 1;
        }
        QVERIFY(editedLine > 0);  // the edit applied

        const SessionInfoParse p = parseSessionInfo(text, "session.yml");
        QVERIFY2(p.ok(), p.error ? p.error->toString().c_str() : "");
        const auto it = std::find_if(p.warnings.begin(), p.warnings.end(),
                                     [&](const SessionIssue& w) { return w.kind == kind; });
        QVERIFY2(it != p.warnings.end(), qPrintable(listed(p.warnings)));
        const SessionIssue& w = *it;
        QCOMPARE(QString::fromStdString(w.key), key);
        QCOMPARE(w.file, std::string("session.yml"));
        if (knowsLine) QCOMPARE(w.line, editedLine);
        // Only the typo'd camera key leaves a second warning: camera.gain is now missing.
        QCOMPARE(int(p.warnings.size()), key == "camera.gian" ? 2 : 1);
        // The default stays where a value was refused.
        const bool gainRefused = key == "camera.gain" || key == "camera.gian";
        QCOMPARE(p.info.camera.gain, gainRefused ? CameraSettings{}.gain : exampleInfo().camera.gain);
    }

    void sessionInfoErrors_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<SessionIssueKind>("kind");
        QTest::addColumn<int>("line");
        QTest::newRow("empty") << "" << SessionIssueKind::ParseError << 0;
        QTest::newRow("not YAML") << "session_format: 1\nframe_count: [1, 2\nnotes: x\n" << SessionIssueKind::ParseError << -1;
        QTest::newRow("no session_format") << "frame_count: 3\n" << SessionIssueKind::NotASession << 0;
        QTest::newRow("format as text") << "session_format: one\n" << SessionIssueKind::NotASession << 0;
        QTest::newRow("future format") << "session_format: 7\n" << SessionIssueKind::UnknownFormat << 0;
    }

    void sessionInfoErrors()
    {
        QFETCH(QString, text);
        QFETCH(SessionIssueKind, kind);
        QFETCH(int, line);
        const SessionInfoParse p = parseSessionInfo(text.toStdString(), "s/session.yml");
        QVERIFY(!p.ok());
        QCOMPARE(p.error->kind, kind);
        QCOMPARE(p.error->file, std::string("s/session.yml"));
        if (line >= 0) QCOMPARE(p.error->line, line);
        else QVERIFY2(p.error->line > 0, p.error->toString().c_str());  // a YAML error knows its line
    }

    void truthRoundTrip()
    {
        std::map<int, TruthRow> rows;
        for (int f : {0, 1, 2, 5, 11, 12, 40}) rows[f] = truthFor(f);
        rows[12].px = 0.1;
        rows[12].yM = -1e-7;
        rows[12].radiusPx = 12.3456789;
        const std::string text = serializeTruthCsv(rows);
        QVERIFY(text.rfind("frame,ball_visible,px,py,radius_px,x_m,y_m,robot_x,robot_y,robot_heading\n", 0) == 0);
        QVERIFY(text.find("\n2,0,,,,,,1.25,-3.5,0.2") != std::string::npos);  // invisible: ball cells empty
        QVERIFY(text.find("\n1,1,11.5,20.25,3.1,-1.4,0.6666666666666666,,,\n") != std::string::npos);
        const TruthParse p = parseTruthCsv(text, "truth.csv");
        QVERIFY(p.ok());
        QVERIFY2(p.warnings.empty(), qPrintable(listed(p.warnings)));
        QCOMPARE(p.rows.size(), rows.size());
        for (const auto& [frame, row] : rows) {
            QVERIFY(p.rows.count(frame));
            QVERIFY2(sameTruth(p.rows.at(frame), row), qPrintable(QString("frame %1").arg(frame)));
        }
        QVERIFY(!p.rows.at(1).robot.has_value());  // empty pose cells stay unknown
    }

    void truthColumnsInAnyOrderWithoutPose()
    {
        const TruthParse p = parseTruthCsv("\xEF\xBB\xBFy_m,x_m,radius_px,py,px,ball_visible,frame\r\n"
                                           "0.5,1.5,4,20,10,1,3\r\n"
                                           "\r\n"
                                           ",,,,,0,4\r\n",
                                           "truth.csv");
        QVERIFY(p.ok());
        QVERIFY2(p.warnings.empty(), qPrintable(listed(p.warnings)));
        QCOMPARE(int(p.rows.size()), 2);
        const TruthRow& r = p.rows.at(3);
        QVERIFY(r.ballVisible);
        QCOMPARE(r.px, 10.0);
        QCOMPARE(r.py, 20.0);
        QCOMPARE(r.radiusPx, 4.0);
        QCOMPARE(r.xM, 1.5);
        QCOMPARE(r.yM, 0.5);
        QVERIFY(!p.rows.at(4).ballVisible);
    }

    void truthWarnings_data()
    {
        QTest::addColumn<QString>("badLine");
        QTest::addColumn<SessionIssueKind>("kind");
        QTest::addColumn<QString>("column");
        QTest::addColumn<bool>("rowKept");
        // The bad line is line 3, between two good rows (frames 0 and 9).
        QTest::newRow("decimal comma") << "5,1,12,5,20,3,0.5,0.1,,," << SessionIssueKind::WrongColumnCount << "" << false;
        QTest::newRow("letters in px") << "5,1,12a,20,3,0.5,0.1,,," << SessionIssueKind::BadNumber << "px" << false;
        QTest::newRow("nan radius") << "5,1,12,20,nan,0.5,0.1,,," << SessionIssueKind::BadNumber << "radius_px" << false;
        QTest::newRow("fractional frame") << "5.5,1,12,20,3,0.5,0.1,,," << SessionIssueKind::BadNumber << "frame" << false;
        QTest::newRow("negative frame") << "-5,1,12,20,3,0.5,0.1,,," << SessionIssueKind::BadValue << "frame" << false;
        QTest::newRow("too few cells") << "5,1,12,20" << SessionIssueKind::WrongColumnCount << "" << false;
        QTest::newRow("too many cells") << "5,1,12,20,3,0.5,0.1,,,,7" << SessionIssueKind::WrongColumnCount << "" << false;
        QTest::newRow("duplicate frame") << "0,0,,,,,,,," << SessionIssueKind::DuplicateFrame << "frame" << false;
        QTest::newRow("ball_visible 2") << "5,2,12,20,3,0.5,0.1,,," << SessionIssueKind::BadValue << "ball_visible" << false;
        QTest::newRow("ball_visible yes") << "5,yes,12,20,3,0.5,0.1,,," << SessionIssueKind::BadNumber << "ball_visible" << false;
        QTest::newRow("visible, no pixel") << "5,1,,20,3,0.5,0.1,,," << SessionIssueKind::BadValue << "px" << false;
        QTest::newRow("zero radius") << "5,1,12,20,0,0.5,0.1,,," << SessionIssueKind::BadValue << "radius_px" << false;
        QTest::newRow("half a pose") << "5,1,12,20,3,0.5,0.1,2.0,," << SessionIssueKind::BadValue << "" << false;
        QTest::newRow("pose without heading") << "5,1,12,20,3,0.5,0.1,2.0,1.0," << SessionIssueKind::BadValue << "" << false;
        QTest::newRow("invisible with leftovers") << "5,0,12,20,3,0.5,0.1,,," << SessionIssueKind::BadValue << "" << true;
    }

    void truthWarnings()
    {
        QFETCH(QString, badLine);
        QFETCH(SessionIssueKind, kind);
        QFETCH(QString, column);
        QFETCH(bool, rowKept);
        const std::string text = truthCsvHeader() + "\n0,1,10,20,3,1.5,0.5,,,\n" + badLine.toStdString() +
                                 "\n9,0,,,,,,1,2,3.14\n";
        const TruthParse p = parseTruthCsv(text, "s/truth.csv");
        QVERIFY(p.ok());
        QVERIFY(p.rows.count(0) && p.rows.count(9));  // the good rows around survive
        QCOMPARE(p.rows.at(0).px, 10.0);
        QCOMPARE(p.rows.at(9).robot->heading, 3.14);
        if (rowKept) {
            QVERIFY(p.warnings.empty());
            QVERIFY(p.rows.count(5) && !p.rows.at(5).ballVisible);
            return;
        }
        QCOMPARE(int(p.rows.size()), 2);
        QCOMPARE(int(p.warnings.size()), 1);
        const SessionIssue& w = p.warnings.front();
        QCOMPARE(w.kind, kind);
        QCOMPARE(w.line, 3);
        QCOMPARE(QString::fromStdString(w.key), column);
        QVERIFY2(w.toString().rfind("s/truth.csv:3: ", 0) == 0, w.toString().c_str());
    }

    void truthHeaderProblems_data()
    {
        QTest::addColumn<QString>("text");
        QTest::addColumn<bool>("fails");
        QTest::addColumn<SessionIssueKind>("kind");
        QTest::addColumn<int>("line");
        QTest::newRow("empty file") << "\n\n" << true << SessionIssueKind::ParseError << 0;
        QTest::newRow("no header line") << "0,1,10,20,3,1.5,0.5,,,\n" << true << SessionIssueKind::MissingColumn << 1;
        QTest::newRow("no px column") << "frame,ball_visible,py,radius_px,x_m,y_m\n" << true << SessionIssueKind::MissingColumn << 1;
        QTest::newRow("a column twice") << "frame,frame,ball_visible,px,py,radius_px,x_m,y_m\n" << true
                                        << SessionIssueKind::ParseError << 1;
        QTest::newRow("unknown column kept going")
            << "\nframe,ball_visible,px,py,radius_px,x_m,y_m,confidence\n0,1,1,2,3,4,5,0.9\n" << false
            << SessionIssueKind::UnknownColumn << 2;
        QTest::newRow("only part of the pose columns")
            << "frame,ball_visible,px,py,radius_px,x_m,y_m,robot_x\n0,1,1,2,3,4,5,7\n" << false
            << SessionIssueKind::MissingColumn << 1;
    }

    void truthHeaderProblems()
    {
        QFETCH(QString, text);
        QFETCH(bool, fails);
        QFETCH(SessionIssueKind, kind);
        QFETCH(int, line);
        const TruthParse p = parseTruthCsv(text.toStdString(), "truth.csv");
        QCOMPARE(!p.ok(), fails);
        const SessionIssue& issue = fails ? *p.error : p.warnings.at(0);
        QCOMPARE(issue.kind, kind);
        QCOMPARE(issue.line, line);
        if (!fails) {
            QCOMPARE(int(p.rows.size()), 1);
            QVERIFY(!p.rows.at(0).robot.has_value());
        }
    }

    void truthForUnrecordedFramesIsDropped()
    {
        QTemporaryDir tmp;
        const std::string folder = tmp.filePath("s").toStdString();
        record(folder, 3).finish();
        std::ofstream(folder + "/truth.csv", std::ios::app) << "17,0,,,,,,,,\n";
        const SessionOpen opened = SessionReader::open(folder);
        QVERIFY(opened.ok());
        QCOMPARE(int(opened.reader->truth().size()), 3);
        QVERIFY(!opened.reader->truthFor(17));
        QVERIFY(hasWarning(opened.reader->warnings(), SessionIssueKind::FrameNotRecorded, "frame 17"));
    }

    void naturalOrder_data()
    {
        QTest::addColumn<QString>("a");
        QTest::addColumn<QString>("b");
        QTest::newRow("2 before 10") << "frame2.png" << "frame10.png";
        QTest::newRow("9 before 10") << "img_9.jpg" << "img_10.jpg";
        QTest::newRow("zero-padded equal to plain, then plain order") << "f01.png" << "f1.png";
        QTest::newRow("second number decides") << "run3_frame2.png" << "run3_frame11.png";
        QTest::newRow("prefix first") << "a" << "a1";
        QTest::newRow("text before digits by byte") << "a.png" << "b.png";
        QTest::newRow("huge numbers") << "x99999999999999999998" << "x99999999999999999999";
    }

    void naturalOrder()
    {
        QFETCH(QString, a);
        QFETCH(QString, b);
        QVERIFY(naturalLess(a.toStdString(), b.toStdString()));
        QVERIFY(!naturalLess(b.toStdString(), a.toStdString()));
        QVERIFY(!naturalLess(a.toStdString(), a.toStdString()));
    }

    void imageGlobPlaysInNaturalOrder()
    {
        QTemporaryDir tmp;
        const std::string dir = tmp.filePath("run").toStdString();
        fs::create_directories(dir);
        const std::vector<int> numbers = {10, 2, 1, 9, 100};
        for (int n : numbers) cv::imwrite(dir + "/frame" + std::to_string(n) + ".png", syntheticFrame(n));
        cv::imwrite(dir + "/other3.png", syntheticFrame(3));
        writeFile(dir + "/notes.txt", "not an image");

        auto globbed = ImageGlobSource::open(dir + "/frame*.png");
        QVERIFY2(globbed.ok(), globbed.error.c_str());
        std::vector<std::string> names;
        for (const std::string& f : globbed.source->files()) names.push_back(fs::path(f).filename().string());
        QCOMPARE(names, (std::vector<std::string>{"frame1.png", "frame2.png", "frame9.png", "frame10.png", "frame100.png"}));
        QCOMPARE(globbed.source->frameSize(), kSize);
        Frame f;
        const std::vector<int> expected = {1, 2, 9, 10, 100};
        for (int i = 0; i < 5; ++i) {
            QVERIFY(!globbed.source->read(FrameSource::kNext, f));
            QCOMPARE(f.index, i);
            QVERIFY(identical(f.image, syntheticFrame(expected[std::size_t(i)])));
        }
        QVERIFY(!globbed.source->read(1, f));  // and back
        QVERIFY(identical(f.image, syntheticFrame(2)));

        auto folder = ImageGlobSource::open(dir);
        QVERIFY(folder.ok());
        QCOMPARE(folder.source->frameCount(), 6);  // every image, not notes.txt
        QCOMPARE(fs::path(folder.source->files().back()).filename().string(), std::string("other3.png"));

        cv::imwrite(dir + "/frame5.png", syntheticFrame(5, {32, 24}));
        auto mixed = ImageGlobSource::open(dir + "/frame*.png");
        QVERIFY(mixed.ok());
        const auto err = mixed.source->read(2, f);  // frame1, frame2, frame5
        QVERIFY(err);
        QCOMPARE(err->kind, FrameErrorKind::WrongSize);
        QVERIFY2(err->message.find("frame5.png") != std::string::npos, err->message.c_str());
    }

    void videoSourceSeeksFrameAccurately()
    {
        QTemporaryDir tmp;
        const std::string path = tmp.filePath("clip.avi").toStdString();
        const int n = 12;
        {
            cv::VideoWriter writer(path, cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, kSize);
            QVERIFY(writer.isOpened());
            for (int i = 0; i < n; ++i) writer.write(cv::Mat(kSize, CV_8UC3, cv::Scalar::all(10 + 20 * i)));
        }
        auto opened = VideoSource::open(path);
        QVERIFY2(opened.ok(), opened.error.c_str());
        VideoSource& v = *opened.source;
        QCOMPARE(v.frameCount(), n);
        QCOMPARE(v.frameSize(), kSize);
        QCOMPARE(v.frameRate(), 25.0);
        Frame f;
        for (int i : {7, 0, 11, 3, 4, 5, 2, 9}) {
            const auto err = v.read(i, f);
            QVERIFY2(!err, err ? err->message.c_str() : "");
            QCOMPARE(f.index, i);
            QCOMPARE(f.timestampS, i / 25.0);
            const double level = cv::mean(f.image)[1];
            QVERIFY2(std::abs(level - (10 + 20 * i)) < 4, qPrintable(QString("frame %1 looks like %2").arg(i).arg(level)));
        }
        const auto end = v.read(n, f);
        QVERIFY(end);
        QCOMPARE(end->kind, FrameErrorKind::OutOfRange);
    }

    void factoryPicksTheSource_data()
    {
        QTest::addColumn<QString>("input");  // relative to the scratch folder
        QTest::addColumn<QString>("kind");   // description's first word
        QTest::addColumn<int>("frames");
        QTest::newRow("session folder") << "session" << "session" << 4;
        QTest::newRow("session.yml file") << "session/session.yml" << "session" << 4;
        QTest::newRow("interrupted session (frames only)") << "frames-only" << "session" << 2;
        QTest::newRow("image folder") << "images" << "images" << 3;
        QTest::newRow("glob") << "images/*.png" << "images" << 3;
        QTest::newRow("one image") << "images/b2.png" << "images" << 1;
        QTest::newRow("video") << "clip.avi" << "video" << 5;
    }

    void factoryPicksTheSource()
    {
        QFETCH(QString, input);
        QFETCH(QString, kind);
        QFETCH(int, frames);
        QTemporaryDir tmp;
        const std::string root = tmp.path().toStdString();
        record(root + "/session", 4).finish();
        record(root + "/frames-only", 2).finish();
        fs::remove(root + "/frames-only/session.yml");
        fs::create_directories(root + "/images");
        for (const char* name : {"b2.png", "b10.png", "b1.png"}) cv::imwrite(root + "/images/" + name, syntheticFrame(1));
        {
            cv::VideoWriter writer(root + "/clip.avi", cv::CAP_OPENCV_MJPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                                   10.0, kSize);
            for (int i = 0; i < 5; ++i) writer.write(syntheticFrame(i));
        }

        auto opened = openFrameSource(root + "/" + input.toStdString());
        QVERIFY2(opened.ok(), opened.error.c_str());
        const std::string description = opened.source->description();
        QCOMPARE(QString::fromStdString(description.substr(0, description.find(' '))), kind);
        QCOMPARE(opened.source->frameCount(), frames);
        QCOMPARE(opened.source->frameSize(), kSize);
        if (input == "frames-only") QVERIFY(!opened.warnings.empty());  // the missing session.yml is reported
        Frame f;
        QVERIFY(!opened.source->read(0, f));
        QCOMPARE(f.image.size(), kSize);
    }

    void factoryExplainsBadInput_data()
    {
        QTest::addColumn<QString>("input");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("nonexistent path") << "nowhere/at/all" << "no such file or folder";
        QTest::newRow("empty folder") << "empty" << "neither a recorded session";
        QTest::newRow("glob matching nothing") << "empty/*.png" << "matches no image";
        QTest::newRow("glob in a missing folder") << "gone/*.png" << "no such folder";
        QTest::newRow("a text file") << "notes.txt" << "cannot be opened as a video";
    }

    void factoryExplainsBadInput()
    {
        QFETCH(QString, input);
        QFETCH(QString, mentions);
        QTemporaryDir tmp;
        const std::string root = tmp.path().toStdString();
        fs::create_directories(root + "/empty");
        writeFile(root + "/notes.txt", "hello");
        const std::string path = root + "/" + input.toStdString();
        auto opened = openFrameSource(path);
        QVERIFY(!opened.ok());
        QVERIFY2(opened.error.find(mentions.toStdString()) != std::string::npos, opened.error.c_str());
        QVERIFY2(opened.error.find(path) != std::string::npos, opened.error.c_str());  // names the path
    }
};

QTEST_GUILESS_MAIN(SessionTest)
#include "calib_session_test.moc"

// Colour classes end to end: omnitune-config --upgrade turns an old per-class config into
// colors.classes unchanged in meaning (the exported LUTs are byte-identical), --export-lut writes
// a table that --check-lut (and the core loader) accept and a damaged copy is refused, and a
// pixel's class is the same in the window's pipeline runner, in omnitune-detect --save-stages and
// in core's Pipeline for one config with non-default classes, on every demo frame.
#include "ToolRun.h"

#include "calib/source/FrameSourceFactory.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"
#include "core/LutFile.h"
#include "core/Pipeline.h"
#include "widgets/PipelineRunner.h"

#include <opencv2/imgcodecs.hpp>

#include <QTemporaryDir>
#include <QtTest>

using namespace omnitune;
using tooltest::Run;
using tooltest::runTool;

namespace {

const QString kConfigTool = QStringLiteral(OMNITUNE_CONFIG);
const QString kDetect = QStringLiteral(OMNITUNE_DETECT);
const QString kDemo = QStringLiteral(OMNITUNE_SOURCE_DIR "/sessions/demo");
// A config saved before colors.classes (one section per fixed class), kept as a fuzz seed.
const QString kOldConfig = QStringLiteral(OMNITUNE_SOURCE_DIR "/fuzz/corpus/config/demo.yml");

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

bool writeAll(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly) && f.write(bytes) == bytes.size();
}

}  // namespace

class ColourClassesToolsTest : public QObject {
    Q_OBJECT
private slots:
    void upgradeKeepsTheMeaning()
    {
        QTemporaryDir dir;
        const QString old = dir.filePath("old.yml");
        const QString upgraded = dir.filePath("upgraded.yml");
        QVERIFY(QFile::copy(kOldConfig, old));
        QVERIFY(QFile::copy(kOldConfig, upgraded));
        const Run check = runTool(kConfigTool, {"--check", old});
        QVERIFY2(check.exitedWith(0) && check.err.contains("--upgrade"), qPrintable(check.describe()));

        const Run up = runTool(kConfigTool, {"--upgrade", upgraded});
        QVERIFY2(up.exitedWith(0) && up.err.contains("upgraded: "), qPrintable(up.describe()));
        const QByteArray text = readAll(upgraded);
        QVERIFY(text.contains("classes:") && text.contains("role: field"));
        QVERIFY(!text.contains("h_min:"));  // the old key (squash_min_radius_px holds the letters)
        const Run recheck = runTool(kConfigTool, {"--check", upgraded});
        QVERIFY2(recheck.exitedWith(0) && recheck.out.contains("OK (0 warning(s))"), qPrintable(recheck.describe()));

        // Unchanged in meaning: the compiled tables of the two files are identical over all colours.
        for (const QString& f : {old, upgraded}) {
            const Run exported = runTool(kConfigTool, {"--export-lut", f, f + ".lut"});
            QVERIFY2(exported.exitedWith(0), qPrintable(exported.describe()));
        }
        const QByteArray a = readAll(old + ".lut");
        QVERIFY(a.size() > 1 << 18);
        QCOMPARE(a, readAll(upgraded + ".lut"));
    }

    void exportedLutLoadsAndDamageIsRefused()
    {
        QTemporaryDir dir;
        const QString lut = dir.filePath("colours.lut");
        const Run exported = runTool(kConfigTool, {"--export-lut", kDemo + "/config.yml", lut});
        QVERIFY2(exported.exitedWith(0), qPrintable(exported.describe()));
        const Run ok = runTool(kConfigTool, {"--check-lut", lut});
        QVERIFY2(ok.exitedWith(0) && ok.out.contains("green (field)"), qPrintable(ok.describe()));
        const LutFileLoad load = loadLutFile(lut.toStdString());
        QVERIFY(load.ok());
        const ConfigLoad config = loadConfig((kDemo + "/config.yml").toStdString());
        QVERIFY(load.lut.table == lutFileOf(config.config.colors).table);

        QByteArray bytes = readAll(lut);
        const QByteArray good = bytes;
        bytes[bytes.size() / 2] = char(bytes[bytes.size() / 2] ^ 0x04);
        const QString flipped = dir.filePath("flipped.lut");
        QVERIFY(writeAll(flipped, bytes));
        const Run bad = runTool(kConfigTool, {"--check-lut", flipped});
        QVERIFY2(bad.refused() && bad.err.contains(flipped.toUtf8()) && bad.err.contains("checksum"), qPrintable(bad.describe()));
        const QString cut = dir.filePath("cut.lut");
        QVERIFY(writeAll(cut, good.left(good.size() - 1000)));
        const Run shortRun = runTool(kConfigTool, {"--check-lut", cut});
        QVERIFY2(shortRun.refused() && shortRun.err.contains(cut.toUtf8()), qPrintable(shortRun.describe()));
    }

    // Window, omnitune-detect and core agree pixel by pixel on classes a team would set up: two
    // field classes, yellow on, a red class whose hue wraps through 0.
    void windowDetectAndCoreClassifyAlike()
    {
        ConfigLoad demo = loadConfig((kDemo + "/config.yml").toStdString());
        QVERIFY(demo.ok());
        Config config = demo.config;
        ColourClasses& cl = config.colors.classes;
        cl[std::size_t(ColorClass::Yellow) - 1].enabled = true;
        cl.insert(cl.begin() + 3, ColourClassDef{"dark_green", ColourRole::Field, {0, 90, 0}, true,
                                                 {HsvRange{true, 30, 95, 25, 255, 0, 255}}});
        cl.push_back({"red", ColourRole::Ball, {0, 0, 200}, true, {HsvRange{true, 172, 4, 120, 255, 60, 255}}});
        QTemporaryDir dir;
        const QString configPath = dir.filePath("config.yml");
        QVERIFY(!saveConfig(config, configPath.toStdString()));
        const QString stages = dir.filePath("stages");
        QVERIFY(QDir().mkpath(stages));
        const Run detect = runTool(kDetect, {"--config", configPath, "--input", kDemo, "--out", dir.filePath("d.csv"),
                                             "--save-stages", stages});
        QVERIFY2(detect.exitedWith(0), qPrintable(detect.describe()));

        auto opened = openFrameSource(kDemo.toStdString());
        QVERIFY(opened.ok());
        std::shared_ptr<FrameSource> source = std::move(opened.source);
        const int frames = source->frameCount();
        QVERIFY(frames >= 20);
        Pipeline pipeline(config);
        PipelineRunner runner;
        int checked = 0;
        for (int i = 0; i < frames; ++i) {
            QSignalSpy spy(&runner, &PipelineRunner::finished);
            runner.request(source, 1, i, config, 1);
            QVERIFY(spy.wait(20000));
            const auto run = spy.at(0).at(0).value<std::shared_ptr<const PipelineRun>>();
            QVERIFY2(run && run->error.isEmpty(), run ? qPrintable(run->error) : "no run");
            PipelineResult core;
            pipeline.process(run->frame, run->format, core, true);
            QCOMPARE(cv::countNonZero(core.classes != run->result.classes), 0);
            char name[32];
            std::snprintf(name, sizeof name, "/%06d_segmented.png", i);
            const cv::Mat saved = cv::imread((stages + name).toStdString(), cv::IMREAD_COLOR);
            QVERIFY(!saved.empty());
            // Display colours differ per class, so equal false colours are equal classes.
            cv::Mat diff;
            cv::absdiff(saved, core.stages.segmented, diff);
            QCOMPARE(cv::countNonZero(diff.reshape(1)), 0);
            ++checked;
        }
        QCOMPARE(checked, frames);
    }
};

QTEST_MAIN(ColourClassesToolsTest)
#include "app_colour_classes_test.moc"

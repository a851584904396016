// The fuzzers' corpus (fuzz/corpus/) replayed in the ordinary and the sanitizer builds: every
// seed, real file and past finding loads or fails with a message naming the file and never
// throws, and what loads saves back to text that loads the same. The findings of fuzz/ get a
// named regression case each.
#include "calib/session/Session.h"
#include "calib/session/TruthCsv.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"

#include <QDirIterator>
#include <QtTest>

using namespace omnitune;

namespace {

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

void addCorpusRows(const QString& target)
{
    QTest::addColumn<QString>("path");
    QDirIterator it(QStringLiteral(OMNITUNE_SOURCE_DIR "/fuzz/corpus/") + target, QDir::Files);
    while (it.hasNext()) {
        const QString path = it.next();
        QTest::newRow(qPrintable(QFileInfo(path).fileName())) << path;
    }
}

}  // namespace

class FuzzCorpusTest : public QObject {
    Q_OBJECT
private slots:
    void configSeeds_data() { addCorpusRows("config"); }
    void configSeeds()
    {
        QFETCH(QString, path);
        const ConfigLoad load = parseConfig(readAll(path).toStdString(), "seed.yml");
        if (!load.ok()) {
            QCOMPARE(QString::fromStdString(load.error->file), QStringLiteral("seed.yml"));
            QVERIFY(!load.error->message.empty());
            return;
        }
        const std::string saved = serializeConfig(load.config);
        const ConfigLoad again = parseConfig(saved, "saved.yml");
        QVERIFY2(again.ok(), again.ok() ? "" : again.error->toString().c_str());
        QCOMPARE(serializeConfig(again.config), saved);
    }

    void sessionSeeds_data() { addCorpusRows("session"); }
    void sessionSeeds()
    {
        QFETCH(QString, path);
        const QByteArray bytes = readAll(path);
        const int nul = bytes.indexOf('\0');  // session.yml, NUL, truth.csv (as fuzz_session reads it)
        const std::string yml = (nul < 0 ? bytes : bytes.left(nul)).toStdString();
        const std::string csv = (nul < 0 ? bytes : bytes.mid(nul + 1)).toStdString();

        const SessionInfoParse info = parseSessionInfo(yml, "session.yml");
        if (info.ok()) {
            const std::string saved = serializeSessionInfo(info.info);
            const SessionInfoParse again = parseSessionInfo(saved, "session.yml");
            QVERIFY2(again.ok(), again.ok() ? "" : again.error->toString().c_str());
            QCOMPARE(serializeSessionInfo(again.info), saved);
        } else {
            QVERIFY(!info.error->message.empty());
        }
        const TruthParse truth = parseTruthCsv(csv, "truth.csv");
        if (truth.ok()) {
            const std::string saved = serializeTruthCsv(truth.rows);
            QCOMPARE(serializeTruthCsv(parseTruthCsv(saved, "truth.csv").rows), saved);
        } else {
            QVERIFY(!truth.error->message.empty());
        }
    }

    // Found by fuzz_config: OpenCV's YAML parser threw std::length_error on a key with no name
    // after an indented one, which no caller caught, so --check, the tools and the window died.
    void keyWithoutNameIsAParseError()
    {
        const ConfigLoad load = parseConfig(" n:1\n :", "c.yml");
        QVERIFY(!load.ok());
        QCOMPARE(load.error->kind, ConfigIssueKind::ParseError);
        QVERIFY(QString::fromStdString(load.error->toString()).startsWith("c.yml:"));
        QVERIFY(QString::fromStdString(load.error->toString()).contains("not a valid YAML config"));
        QVERIFY(!parseSessionInfo(" n:1\n :", "session.yml").ok());
    }

    // Found by fuzz_config in CI: OpenCV's reader loops for good on ":---" followed by a control
    // byte. A control byte has no place in a YAML text file: refused before parsing, with its line.
    void controlByteInTheFileIsRefusedBeforeParsing()
    {
        const std::string text = "%YAML:1.0\n t:.\n:---\n\x04";
        const ConfigLoad load = parseConfig(text, "c.yml");
        QVERIFY(!load.ok());
        QCOMPARE(load.error->kind, ConfigIssueKind::ParseError);
        QCOMPARE(load.error->line, 4);
        QVERIFY(QString::fromStdString(load.error->message).contains("control character"));
        QVERIFY(!parseSessionInfo(text, "session.yml").ok());
    }

    // Found by fuzz_config: OpenCV's reader loops for good when a line lies left of the first
    // one (" t: 1", then "x---"): invalid YAML, refused before parsing with its line.
    void lineLeftOfTheFirstIsRefusedBeforeParsing()
    {
        for (const char* text : {" t: 1\nx---\nc", " n:1.0\n t:.\n:---\ncamr,\r\r AM :"}) {
            const ConfigLoad load = parseConfig(text, "c.yml");
            QVERIFY(!load.ok());
            QCOMPARE(load.error->kind, ConfigIssueKind::ParseError);
            QVERIFY(load.error->line == 2 || load.error->line == 3);
            QVERIFY(QString::fromStdString(load.error->message).contains("Incorrect indentation"));
            QVERIFY(!parseSessionInfo(text, "session.yml").ok());
        }
        // Indented documents as such stay readable.
        QVERIFY(parseConfig(" schema: 1\n camera:\n    gain: 100\n", "c.yml").ok());
    }

    // Found by fuzz_config in CI: OpenCV's reader loops for good on a line that is neither
    // "key: value" nor a list item (below a "--- a: 1" line): refused before parsing.
    void strayLineIsRefusedBeforeParsing()
    {
        for (const char* text : {"---ema: 1\n\xba t -\nca1\n   g\x8a\x9a\xdf|\n", "schema: 1\ncamera\n", "a: 1\nb:2\n"}) {
            const ConfigLoad load = parseConfig(text, "c.yml");
            QVERIFY(!load.ok());
            QCOMPARE(load.error->kind, ConfigIssueKind::ParseError);
            QVERIFY2(QString::fromStdString(load.error->message).contains("neither"), load.error->toString().c_str());
        }
    }

    // Found by fuzz_config and fuzz_session: an escape such as "\1" reads as a control character
    // that cv::FileStorage writes as "\x01" and then cannot read: the window saved a config it
    // could not open again. Such text is refused when read.
    void controlCharacterInTextIsRefused()
    {
        const ConfigLoad load = parseConfig("schema: 1\ncamera:\n   model: \"Flea\\1Z\"\n", "c.yml");
        QVERIFY(!load.ok());
        QCOMPARE(QString::fromStdString(load.error->key), QStringLiteral("camera.model"));
        QVERIFY(QString::fromStdString(load.error->message).contains("control character"));

        const SessionInfoParse info = parseSessionInfo("session_format: 1\ncreated: \"\\1Z\"\n", "session.yml");
        QVERIFY(info.ok());  // a session keeps loading; the value is dropped with a warning
        QVERIFY(info.info.created.empty());
        bool warned = false;
        for (const SessionIssue& w : info.warnings)
            warned |= w.key == "created" && QString::fromStdString(w.message).contains("control character");
        QVERIFY(warned);
        QVERIFY(parseSessionInfo(serializeSessionInfo(info.info), "session.yml").ok());

        // Tabs and line breaks are text, and survive a save.
        const ConfigLoad tab = parseConfig("schema: 1\ncamera:\n   model: \"a\\tb\\nc\"\n", "c.yml");
        QVERIFY(tab.ok());
        QCOMPARE(QString::fromStdString(tab.config.camera.model), QStringLiteral("a\tb\nc"));
    }

    // Found by fuzz_session: cv::FileStorage's << takes a text starting with [ { ] } for the
    // start or end of a list or map, so serializing a model or notes like "]x" threw (the window
    // died saving the config) and "[test]" wrote a file that could not be read.
    void textStartingWithABracketSavesAndLoads_data()
    {
        QTest::addColumn<QString>("text");
        QTest::newRow("closing bracket") << "]x";
        QTest::newRow("closing brace") << "}";
        QTest::newRow("list") << "[test]";
        QTest::newRow("map") << "{a: 1}";
    }
    void textStartingWithABracketSavesAndLoads()
    {
        QFETCH(QString, text);
        Config config;
        config.camera.model = text.toStdString();
        const ConfigLoad load = parseConfig(serializeConfig(config), "c.yml");
        QVERIFY2(load.ok(), load.ok() ? "" : load.error->toString().c_str());
        QCOMPARE(QString::fromStdString(load.config.camera.model), text);

        SessionInfo info;
        info.notes = text.toStdString();
        info.camera.model = text.toStdString();
        info.created = text.toStdString();
        const SessionInfoParse parse = parseSessionInfo(serializeSessionInfo(info), "session.yml");
        QVERIFY(parse.ok());
        QCOMPARE(QString::fromStdString(parse.info.notes), text);
        QCOMPARE(QString::fromStdString(parse.info.camera.model), text);
        QCOMPARE(QString::fromStdString(parse.info.created), text);
    }
};

QTEST_GUILESS_MAIN(FuzzCorpusTest)
#include "calib_fuzz_corpus_test.moc"

// The exported LUT file (core/LutFile.h): a round trip gives the same table, classes and flags;
// a flipped byte, a cut file, a wrong magic or a wrong size are refused with the file named.
#include "core/LutFile.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace omnitune;

class LutFileTest : public QObject {
    Q_OBJECT
private slots:
    void roundTrip_data()
    {
        QTest::addColumn<int>("bits");
        QTest::addColumn<bool>("relative");
        QTest::newRow("6 bits, relative black") << 6 << true;
        QTest::newRow("4 bits, fixed black") << 4 << false;
    }
    void roundTrip()
    {
        QFETCH(int, bits);
        QFETCH(bool, relative);
        ColorLutOptions o;
        o.bits = bits;
        o.blackRelative = relative;
        o.classes.push_back({"red", ColourRole::Ball, {0, 0, 200}, true, {HsvRange{true, 172, 4, 120, 255, 60, 255}}});
        const LutFile lut = lutFileOf(o);
        QCOMPARE(int(lut.table.size()), 1 << (3 * bits));
        QTemporaryDir dir;
        const std::string path = dir.filePath("c.lut").toStdString();
        QVERIFY(!saveLutFile(lut, path));
        const LutFileLoad back = loadLutFile(path);
        QVERIFY2(back.ok(), back.ok() ? "" : back.error->toString().c_str());
        QVERIFY(back.lut.table == lut.table);
        QCOMPARE(back.lut.bits, bits);
        QCOMPARE(back.lut.blackRelative, relative);
        QCOMPARE(int(back.lut.classes.size()), int(o.classes.size()));
        QCOMPARE(back.lut.classes.back().name, std::string("red"));
        QCOMPARE(back.lut.classes.back().role, ColourRole::Ball);
        QCOMPARE(back.lut.classes.back().display, (std::array<std::uint8_t, 3>{0, 0, 200}));
        // The table is the LUT's own classification of each bin.
        const ColorLut direct(o);
        const int shift = 8 - bits;
        const std::size_t red = (std::size_t(20 >> shift) << (2 * bits)) | (std::size_t(20 >> shift) << bits) | std::size_t(220 >> shift);
        QCOMPARE(ColorClass(back.lut.table[red]), direct.classifyBgr(20, 20, 220));
    }

    void damageIsRefused_data()
    {
        QTest::addColumn<QString>("damage");
        QTest::addColumn<QString>("says");
        QTest::newRow("flipped table byte") << "flip-table" << "checksum";
        QTest::newRow("flipped header byte") << "flip-header" << "checksum";
        QTest::newRow("cut short") << "cut" << "checksum";
        QTest::newRow("wrong magic") << "magic" << "magic";
        QTest::newRow("empty") << "empty" << "magic";
        QTest::newRow("entry count of other bits") << "entries" << "entry count";
    }
    void damageIsRefused()
    {
        QFETCH(QString, damage);
        QFETCH(QString, says);
        std::string bytes = encodeLutFile(lutFileOf(ColorLutOptions{}));
        if (damage == "flip-table") bytes[bytes.size() / 2] ^= 0x01;
        if (damage == "flip-header") bytes[13] ^= 0x10;
        if (damage == "cut") bytes.resize(bytes.size() - 100);
        if (damage == "magic") bytes[0] = 'X';
        if (damage == "empty") bytes.clear();
        if (damage == "entries") {
            LutFile odd = lutFileOf(ColorLutOptions{});
            odd.table.resize(odd.table.size() / 2);  // consistent checksum, wrong size for its bits
            bytes = encodeLutFile(odd);
        }
        QTemporaryDir dir;
        const std::string path = dir.filePath("bad.lut").toStdString();
        QFile f(QString::fromStdString(path));
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write(bytes.data(), qint64(bytes.size()));
        f.close();
        const LutFileLoad load = loadLutFile(path);
        QVERIFY(!load.ok());
        QCOMPARE(load.error->file, path);
        QVERIFY2(QString::fromStdString(load.error->message).contains(says), load.error->toString().c_str());
    }

    void missingFileIsNamed()
    {
        const LutFileLoad load = loadLutFile("/nonexistent/x.lut");
        QVERIFY(!load.ok());
        QCOMPARE(load.error->file, std::string("/nonexistent/x.lut"));
    }
};

QTEST_GUILESS_MAIN(LutFileTest)
#include "core_lut_file_test.moc"

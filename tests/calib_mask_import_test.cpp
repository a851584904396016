// A mask made elsewhere (calib/mask/MaskImport): both conventions, colours counted as bright,
// and the refusals the window and omnitune-calibrate share: another size, all one value.
#include "calib/mask/MaskImport.h"

#include <opencv2/imgproc.hpp>

#include <QtTest>

using namespace omnitune;

namespace {

GeometryOptions smallCamera()
{
    GeometryOptions g;
    g.imageWidth = 120;
    g.imageHeight = 100;
    g.centerX = 60;
    g.centerY = 50;
    g.innerRadius = 10;
    g.outerRadius = 45;
    return g;
}

// Another team's convention: red robot (a rod) on black, black = process.
cv::Mat redRodOnBlack()
{
    cv::Mat image(100, 120, CV_8UC3, cv::Scalar(0, 0, 0));
    cv::rectangle(image, cv::Rect(58, 0, 5, 50), cv::Scalar(0, 0, 255), cv::FILLED);
    return image;
}

}  // namespace

class MaskImportTest : public QObject {
    Q_OBJECT
private slots:
    void darkProcessesTakesTheRedRodAsRobot()
    {
        const MaskImportResult r = importMask(redRodOnBlack(), MaskConvention::DarkProcesses, smallCamera());
        QVERIFY(r.ok());
        QCOMPARE(r.fit.mask.type(), CV_8UC1);
        QCOMPARE(int(r.fit.mask.at<std::uint8_t>(20, 60)), 0);    // the rod
        QCOMPARE(int(r.fit.mask.at<std::uint8_t>(80, 60)), 255);  // the field
        QVERIFY(r.fit.processedShare > 0.9);
    }

    void theOtherWayRoundLeavesMostOfTheRingOut()
    {
        const MaskImportResult r = importMask(redRodOnBlack(), MaskConvention::BrightProcesses, smallCamera());
        QVERIFY(r.ok());
        QCOMPARE(int(r.fit.mask.at<std::uint8_t>(20, 60)), 255);
        QVERIFY(r.fit.processedShare < 0.1);
    }

    void allOneValueIsRefused_data()
    {
        QTest::addColumn<int>("grey");
        QTest::addColumn<int>("convention");
        QTest::addColumn<QString>("says");
        QTest::newRow("white, white processes") << 255 << int(MaskConvention::BrightProcesses) << "every pixel";
        QTest::newRow("white, black processes") << 255 << int(MaskConvention::DarkProcesses) << "no pixel";
        QTest::newRow("black, white processes") << 0 << int(MaskConvention::BrightProcesses) << "no pixel";
    }
    void allOneValueIsRefused()
    {
        QFETCH(int, grey);
        QFETCH(int, convention);
        QFETCH(QString, says);
        const MaskImportResult r = importMask(cv::Mat(100, 120, CV_8UC1, cv::Scalar(grey)), MaskConvention(convention), smallCamera());
        QVERIFY(!r.ok());
        QCOMPARE(r.error->kind, FitErrorKind::Uniform);
        const QString message = QString::fromStdString(r.error->toString());
        QVERIFY2(message.contains("all one value") && message.contains(says), qPrintable(message));
        QVERIFY(r.fit.mask.empty());
    }

    void anotherSizeIsRefusedWithBothSizes()
    {
        const MaskImportResult r = importMask(cv::Mat(50, 60, CV_8UC1, cv::Scalar(255)), MaskConvention::BrightProcesses, smallCamera());
        QVERIFY(!r.ok());
        const QString message = QString::fromStdString(r.error->toString());
        QVERIFY2(message.contains("60x50") && message.contains("120x100"), qPrintable(message));
    }
};

QTEST_GUILESS_MAIN(MaskImportTest)
#include "calib_mask_import_test.moc"

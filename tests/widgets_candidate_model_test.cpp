// The candidate table (thesis Table 4.1 extended): a well-behaved Qt model, the texts of each
// column, the accepted row highlighted, the failing score of a rejected row in red.
#include "widgets/CandidateTableModel.h"
#include "core/Config.h"

#include <QAbstractItemModelTester>
#include <QBrush>
#include <QSignalSpy>
#include <QtTest>

Q_DECLARE_METATYPE(omnitune::RejectReason)

using namespace omnitune;
using Col = CandidateTableModel::Column;

namespace {

BallCandidate makeCandidate(CandidateSource source, int area, int x, int y, RejectReason rejected)
{
    BallCandidate c;
    c.source = source;
    c.area = area;
    c.x = x;
    c.y = y;
    c.rejected = rejected;
    return c;
}

// Scores as validation leaves them: every test measured, or only the colour square (a prefilter
// refusal, or a colour refusal on the robot, which stops there).
ValidationScores measured(double nonGreen, double nonBlack, double circularity, double runOn)
{
    ValidationScores s;
    s.nonGreenPct = nonGreen;
    s.nonBlackPct = nonBlack;
    s.circularityPct = circularity;
    s.runOnPct = runOn;
    s.squareMeasured = s.shapeMeasured = true;
    return s;
}

ValidationScores colourOnly(double nonGreen, double nonBlack)
{
    ValidationScores s;
    s.nonGreenPct = nonGreen;
    s.nonBlackPct = nonBlack;
    s.squareMeasured = true;
    return s;
}

// One accepted specific-Hough ball and one OpenCV circle rejected by circularity.
PipelineResult twoCandidates()
{
    PipelineResult r;
    BallCandidate ball = makeCandidate(CandidateSource::SpecificHough, 2, 312, 187, RejectReason::None);
    ball.radiusPx = 7.26;
    ball.expectedRadiusPx = 7.26;
    ball.distancePx = 131.04;
    ball.accumulator = 412;
    ball.scores = measured(96.44, 88.06, 91.67, 0.4);
    BallCandidate line = makeCandidate(CandidateSource::OpenCvHough, -1, 90, 401, RejectReason::Circularity);
    line.radiusPx = 11.5;
    line.expectedRadiusPx = 10.92;
    line.distancePx = 212.3;
    line.scores = measured(91.2, 77.7, 41.66, 2.1);
    line.scores.fitRadiusPx = 11.3;  // the expected size: in the clear
    r.candidates = {ball, line};
    r.detection.found = true;
    r.detection.candidate = 0;
    return r;
}

PipelineResult withCount(int n)
{
    PipelineResult r;
    for (int i = 0; i < n; ++i)
        r.candidates.push_back(makeCandidate(CandidateSource::SpecificHough, i, 10 * i, 20 * i,
                                             i == 0 ? RejectReason::None : RejectReason::NotChosen));
    return r;
}

bool reddish(const QVariant& v)
{
    const QColor c = v.value<QBrush>().color();
    return v.isValid() && c.red() > c.green() + 40 && c.red() > c.blue() + 40;
}

bool greenish(const QVariant& v)
{
    const QColor c = v.value<QBrush>().color();
    return v.isValid() && c.green() > c.red() + 20 && c.green() > c.blue() + 20;
}

}  // namespace

class CandidateModelTest : public QObject {
    Q_OBJECT
private slots:
    void resetsUnderModelTester();
    void displayTexts_data();
    void displayTexts();
    void acceptedRowHighlighted();
    void failingCellRed_data();
    void failingCellRed();
    void headerAndTooltips();
    void thresholdsInTooltips();
    void candidateAccessor();
    void prefilterRefusalsShowNoShape();
    void recentredRefusalsShowTheirShape();
    void refittedCandidatesSayTheyMoved();
    void unmeasuredScoresShowADash();
};

void CandidateModelTest::resetsUnderModelTester()
{
    CandidateTableModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    QSignalSpy resets(&model, &QAbstractItemModel::modelReset);
    QCOMPARE(model.rowCount(), 0);
    QCOMPARE(model.columnCount(), int(Col::ColumnCount));
    int expectedResets = 0;
    for (int n : {0, 3, 1, 0, 2}) {
        model.setResult(withCount(n), Config{});
        QCOMPARE(resets.count(), ++expectedResets);
        QCOMPARE(model.rowCount(), n);
        QCOMPARE(model.rowCount(model.index(0, 0)), 0);  // a table: no children
        QCOMPARE(model.acceptedRow(), n > 0 ? 0 : -1);
        for (int row = 0; row < n; ++row) QCOMPARE(model.index(row, Col::XColumn).data().toString(), QString::number(10 * row));
    }
    model.clear();
    QCOMPARE(model.rowCount(), 0);
}

void CandidateModelTest::displayTexts_data()
{
    QTest::addColumn<int>("row");
    QTest::addColumn<int>("column");
    QTest::addColumn<QString>("text");
    QTest::newRow("area is 1-based") << 0 << int(Col::AreaColumn) << "3";
    QTest::newRow("no area for OpenCV") << 1 << int(Col::AreaColumn) << "-";
    QTest::newRow("source specific") << 0 << int(Col::SourceColumn) << "specific";
    QTest::newRow("source opencv") << 1 << int(Col::SourceColumn) << "opencv";
    QTest::newRow("x") << 0 << int(Col::XColumn) << "312";
    QTest::newRow("y") << 1 << int(Col::YColumn) << "401";
    QTest::newRow("radius 1 decimal") << 0 << int(Col::RadiusColumn) << "7.3";
    QTest::newRow("distance") << 1 << int(Col::DistanceColumn) << "212.3";
    QTest::newRow("accumulator") << 0 << int(Col::AccumulatorColumn) << "412";
    QTest::newRow("no votes for OpenCV") << 1 << int(Col::AccumulatorColumn) << "-";
    QTest::newRow("non-green") << 0 << int(Col::NonGreenColumn) << "96.4";
    QTest::newRow("non-black") << 1 << int(Col::NonBlackColumn) << "77.7";
    QTest::newRow("circularity") << 1 << int(Col::CircularityColumn) << "41.7";
    QTest::newRow("accepted") << 0 << int(Col::ResultColumn) << "accepted";
    QTest::newRow("rejected") << 1 << int(Col::ResultColumn) << "circularity";
}

void CandidateModelTest::displayTexts()
{
    QFETCH(int, row);
    QFETCH(int, column);
    QFETCH(QString, text);
    CandidateTableModel model;
    model.setResult(twoCandidates(), Config{});
    QCOMPARE(model.rowCount(), 2);
    QCOMPARE(model.index(row, column).data(Qt::DisplayRole).toString(), text);
}

void CandidateModelTest::acceptedRowHighlighted()
{
    CandidateTableModel model;
    model.setResult(twoCandidates(), Config{});
    QCOMPARE(model.acceptedRow(), 0);
    for (int col = 0; col < model.columnCount(); ++col) {
        QVERIFY2(greenish(model.index(0, col).data(Qt::BackgroundRole)), qPrintable(QString::number(col)));
        QVERIFY(!greenish(model.index(1, col).data(Qt::BackgroundRole)));
    }
    QVERIFY(model.index(0, Col::XColumn).data(Qt::FontRole).value<QFont>().bold());
}

void CandidateModelTest::failingCellRed_data()
{
    QTest::addColumn<RejectReason>("reason");
    QTest::addColumn<int>("failing");  // -1: no score cell is red
    QTest::newRow("circularity") << RejectReason::Circularity << int(Col::CircularityColumn);
    QTest::newRow("non-green") << RejectReason::NonGreen << int(Col::NonGreenColumn);
    QTest::newRow("non-black") << RejectReason::NonBlack << int(Col::NonBlackColumn);
    QTest::newRow("too far") << RejectReason::TooSmall << int(Col::RadiusColumn);
    QTest::newRow("radius too large") << RejectReason::RadiusTooLarge << int(Col::RadiusColumn);
    QTest::newRow("runs on") << RejectReason::RunsOn << int(Col::RunOnColumn);
    QTest::newRow("valid, not chosen") << RejectReason::NotChosen << -1;
}

void CandidateModelTest::failingCellRed()
{
    QFETCH(RejectReason, reason);
    QFETCH(int, failing);
    PipelineResult r = twoCandidates();
    r.candidates[1].rejected = reason;
    CandidateTableModel model;
    model.setResult(r, Config{});
    for (int col = 0; col < model.columnCount(); ++col) {
        const QModelIndex cell = model.index(1, col);
        const bool red = col == failing;
        QCOMPARE(reddish(cell.data(Qt::BackgroundRole)), red);
        QCOMPARE(reddish(cell.data(Qt::ForegroundRole)), red || (col == Col::ResultColumn && failing >= 0));
        QCOMPARE(reddish(model.index(0, col).data(Qt::BackgroundRole)), false);
    }
    if (failing >= 0) QVERIFY(model.index(1, failing).data(Qt::ToolTipRole).toString().contains(QStringLiteral("Rejected here")));
}

void CandidateModelTest::headerAndTooltips()
{
    CandidateTableModel model;
    model.setResult(twoCandidates(), Config{});
    QCOMPARE(model.headerData(Col::CircularityColumn, Qt::Horizontal).toString(), QStringLiteral("circ.\n%"));
    QCOMPARE(model.headerData(Col::ResultColumn, Qt::Horizontal).toString(), QStringLiteral("Result"));
    QStringList headers;
    for (int col = 0; col < model.columnCount(); ++col) {
        const QString header = model.headerData(col, Qt::Horizontal).toString();
        QVERIFY(!header.isEmpty());
        QVERIFY(!headers.contains(header));
        headers << header;
        QVERIFY2(model.headerData(col, Qt::Horizontal, Qt::ToolTipRole).toString().size() > 20, qPrintable(header));
        QCOMPARE(model.index(0, col).data(Qt::ToolTipRole).toString().left(20),
                 model.headerData(col, Qt::Horizontal, Qt::ToolTipRole).toString().left(20));
    }
    const QString circ = model.headerData(Col::CircularityColumn, Qt::Horizontal, Qt::ToolTipRole).toString();
    QVERIFY2(circ.contains(QStringLiteral("validation.min_circularity_pct")) && circ.contains(QStringLiteral("70.0 %")), qPrintable(circ));
    QVERIFY2(circ.contains(QStringLiteral("validation.min_circularity_clear_pct")) && circ.contains(QStringLiteral("60.0 %")) &&
                 circ.contains(QStringLiteral("within 15 %")),
             qPrintable(circ));
    // The circle is in the clear (77.7 % non-black, fitted at its size): it is held to the clear threshold.
    const QString failed = model.index(1, Col::CircularityColumn).data(Qt::ToolTipRole).toString();
    QVERIFY2(failed.contains(QStringLiteral("41.7 % is below 60.0 %")), qPrintable(failed));
    // Fitted 20 % smaller than expected (validation.clear_max_fit_error): the thesis' 70 %.
    PipelineResult small = twoCandidates();
    small.candidates[1].scores.fitRadiusPx = 8.7;
    model.setResult(small, Config{});
    const QString offSize = model.index(1, Col::CircularityColumn).data(Qt::ToolTipRole).toString();
    QVERIFY2(offSize.contains(QStringLiteral("41.7 % is below 70.0 %")), qPrintable(offSize));
    // Beside a robot (below validation.clear_min_non_black_pct) it is held to the thesis' 70 %.
    PipelineResult beside = twoCandidates();
    beside.candidates[1].scores.nonBlackPct = 50.0;
    model.setResult(beside, Config{});
    const QString held = model.index(1, Col::CircularityColumn).data(Qt::ToolTipRole).toString();
    QVERIFY2(held.contains(QStringLiteral("41.7 % is below 70.0 %")), qPrintable(held));
}

void CandidateModelTest::thresholdsInTooltips()
{
    // The tooltips quote the config the result was computed with, not one of their own.
    CandidateTableModel model;
    QAbstractItemModelTester tester(&model, QAbstractItemModelTester::FailureReportingMode::QtTest);
    PipelineResult r = twoCandidates();
    r.candidates[1].rejected = RejectReason::NonGreen;
    model.setResult(r, Config{});
    Config config;
    config.validation.minNonGreenPct = 62.5;
    model.setResult(r, config);
    const QString failed = model.index(1, Col::NonGreenColumn).data(Qt::ToolTipRole).toString();
    QVERIFY2(failed.contains(QStringLiteral("below 62.5 %")), qPrintable(failed));
    const QString tip = model.headerData(Col::NonGreenColumn, Qt::Horizontal, Qt::ToolTipRole).toString();
    QVERIFY2(tip.contains(QStringLiteral("62.5 %")) && tip.contains(QStringLiteral("validation.min_non_green_pct")), qPrintable(tip));
}

void CandidateModelTest::candidateAccessor()
{
    CandidateTableModel model;
    const PipelineResult r = twoCandidates();
    model.setResult(r, Config{});
    QCOMPARE(model.candidate(1).x, 90);
    QCOMPARE(model.candidate(1).rejected, RejectReason::Circularity);
    QCOMPARE(model.candidate(0).accumulator, 412.0);
    QCOMPARE(model.index(1, Col::CircularityColumn).data(CandidateTableModel::SortRole).toDouble(), 41.66);
}

// The specific search lists its prefilter refusals after its candidates (with every refusal
// listed: the strongest per area, then the rest), and OpenCV's circles come after them: the
// refusals' circularity and run-on were never measured, and say so.
void CandidateModelTest::prefilterRefusalsShowNoShape()
{
    PipelineResult r = twoCandidates();
    BallCandidate refused = makeCandidate(CandidateSource::SpecificHough, 3, 200, 100, RejectReason::NonGreen);
    refused.scores = colourOnly(40.0, 100.0);
    BallCandidate pastTheCap = makeCandidate(CandidateSource::SpecificHough, 4, 210, 90, RejectReason::NonGreen);
    pastTheCap.scores = colourOnly(30.0, 100.0);
    r.candidates.insert(r.candidates.begin() + 1, {refused, pastTheCap});  // before OpenCV's circle
    r.hough.prefilterListed = 1;
    r.hough.prefilterUnlisted = 1;
    CandidateTableModel model;
    model.setResult(r, Config{});
    QVERIFY(!model.isPrefiltered(0));
    QVERIFY(model.isPrefiltered(1));
    QVERIFY(model.isPrefiltered(2));
    QVERIFY(!model.isPrefiltered(3));
    QCOMPARE(model.index(1, Col::CircularityColumn).data().toString(), QString("-"));
    QCOMPARE(model.index(1, Col::RunOnColumn).data().toString(), QString("-"));
    QCOMPARE(model.index(1, Col::NonGreenColumn).data().toString(), QString("40.0"));
    QCOMPARE(model.index(2, Col::CircularityColumn).data().toString(), QString("-"));
    QVERIFY(!model.index(1, Col::CircularityColumn).data(CandidateTableModel::SortRole).isValid());
    QVERIFY(model.index(1, Col::ResultColumn).data(Qt::ToolTipRole).toString().contains("Not validated"));
    QVERIFY(model.index(2, Col::ResultColumn).data(Qt::ToolTipRole).toString().contains("Not validated"));
    QCOMPARE(model.index(3, Col::CircularityColumn).data().toString(), QString("41.7"));
    QVERIFY(!model.index(3, Col::ResultColumn).data(Qt::ToolTipRole).toString().contains("Not validated"));
}

// validation.recentre_refused validates a refusal again at a new centre and puts the ones that
// passed before the refusals still listed: those rows show their measured shape and say how they
// got there; the listed refusals after them still show none.
void CandidateModelTest::recentredRefusalsShowTheirShape()
{
    PipelineResult r = twoCandidates();
    r.candidates[0].rejected = RejectReason::NotChosen;
    BallCandidate moved = makeCandidate(CandidateSource::SpecificHough, 4, 240, 130, RejectReason::None);
    moved.scores = measured(81.5, 100.0, 88.34, 0.0);
    moved.move = CandidateMove::ToColourCentroid;
    moved.searchX = 236;
    moved.searchY = 127;
    BallCandidate refused = makeCandidate(CandidateSource::SpecificHough, 5, 200, 100, RejectReason::NonGreen);
    refused.scores = colourOnly(40.0, 100.0);
    r.candidates.insert(r.candidates.begin() + 1, {moved, refused});  // before OpenCV's circle
    r.hough.prefilterListed = 1;
    r.hough.recentreTried = 1;
    r.hough.recentred = 1;
    r.detection.candidate = 1;
    CandidateTableModel model;
    model.setResult(r, Config{});
    QVERIFY(!model.isRecentred(0));
    QVERIFY(model.isRecentred(1));
    QVERIFY(!model.isPrefiltered(1));
    QVERIFY(model.isPrefiltered(2));
    QVERIFY(!model.isRecentred(3));
    QCOMPARE(model.acceptedRow(), 1);
    QCOMPARE(model.index(1, Col::CircularityColumn).data().toString(), QString("88.3"));
    QVERIFY(model.index(1, Col::ResultColumn).data(Qt::ToolTipRole).toString().contains("Recentred from (236, 127)"));
    QCOMPARE(model.index(1, Col::ResultColumn).data().toString(), QString("accepted, moved"));
    QVERIFY(!model.index(1, Col::ResultColumn).data(Qt::ToolTipRole).toString().contains("Not validated"));
    QCOMPARE(model.index(2, Col::CircularityColumn).data().toString(), QString("-"));
    QVERIFY(!model.index(2, Col::ResultColumn).data(Qt::ToolTipRole).toString().contains("Recentred"));
}

// validation.refit_recentre replaces a circularity refusal in place by the candidate at its fitted
// centre: nothing in the row's position says so, so the verdict and the tooltips do, with where
// the search had put it; an unmoved row says nothing of a move.
void CandidateModelTest::refittedCandidatesSayTheyMoved()
{
    PipelineResult r = twoCandidates();
    r.candidates[0].move = CandidateMove::ToCircleFit;
    r.candidates[0].searchX = r.candidates[0].x - 4;
    r.candidates[0].searchY = r.candidates[0].y + 3;
    CandidateTableModel model;
    model.setResult(r, Config{});
    const QString from = QString("(%1, %2)").arg(r.candidates[0].searchX).arg(r.candidates[0].searchY);
    QVERIFY(model.index(0, Col::ResultColumn).data().toString().endsWith(", moved"));
    for (int column : {int(Col::ResultColumn), int(Col::XColumn), int(Col::YColumn)}) {
        const QString tip = model.index(0, column).data(Qt::ToolTipRole).toString();
        QVERIFY2(tip.contains("Moved to its fit from " + from) && tip.contains("refit_recentre"), qPrintable(tip));
    }
    QVERIFY(!model.index(0, Col::NonGreenColumn).data(Qt::ToolTipRole).toString().contains("Moved"));
    QVERIFY(!model.index(1, Col::ResultColumn).data().toString().contains("moved"));
    QVERIFY(!model.index(1, Col::ResultColumn).data(Qt::ToolTipRole).toString().contains("Moved"));
    QVERIFY(!model.isRecentred(0));  // not a prefilter refusal: its row stays where the search listed it
}

// A pipeline that does not explain its rejections stops at a failed colour test: that row's shape
// was never measured and shows "-" like a prefilter refusal's (not a 0 that reads as a failure);
// an OpenCV circle refused before validation has no colour scores either.
void CandidateModelTest::unmeasuredScoresShowADash()
{
    PipelineResult r = twoCandidates();
    r.candidates[1].rejected = RejectReason::NonGreen;
    r.candidates[1].scores = colourOnly(31.0, 100.0);
    BallCandidate outside = makeCandidate(CandidateSource::OpenCvHough, -1, 5, 5, RejectReason::OutsideArea);
    r.candidates.push_back(outside);
    CandidateTableModel model;
    model.setResult(r, Config{});
    QVERIFY(!model.isPrefiltered(1));
    QCOMPARE(model.index(1, Col::NonGreenColumn).data().toString(), QString("31.0"));
    QCOMPARE(model.index(1, Col::CircularityColumn).data().toString(), QString("-"));
    QCOMPARE(model.index(1, Col::RunOnColumn).data().toString(), QString("-"));
    QVERIFY(!model.index(1, Col::CircularityColumn).data(CandidateTableModel::SortRole).isValid());
    QCOMPARE(model.index(2, Col::NonGreenColumn).data().toString(), QString("-"));
    QCOMPARE(model.index(2, Col::NonBlackColumn).data().toString(), QString("-"));
    QCOMPARE(model.index(0, Col::CircularityColumn).data().toString(), QString("91.7"));
}

QTEST_MAIN(CandidateModelTest)
#include "widgets_candidate_model_test.moc"

// Overlay labels near the robot (widgets/LabelPlacement and the pane that uses it): on a crowded
// synthetic candidate set no two labels overlap or touch and all stay inside the pane; a lone label sits
// right beside its circle; a label moved away gets a leader line; and a real ImageView painting
// a crowded overlay places its labels the same way and explains a candidate in its tooltip; a
// candidate a second look moved is drawn with where the search had put it.
#include "widgets/ImageView.h"
#include "widgets/LabelPlacement.h"

#include <QToolTip>
#include <QtTest>

#include <random>

using namespace omnitune;

namespace {

// Whether two of `boxes` overlap, or (with `gap`) come nearer than `gap` px to each other.
bool anyOverlap(const std::vector<QRectF>& boxes, double gap = 0.0)
{
    const double g = std::max(gap - 0.01, 0.0);  // exactly `gap` apart is apart
    for (std::size_t i = 0; i < boxes.size(); ++i)
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
            if (boxes[i].adjusted(-g, -g, g, g).intersects(boxes[j])) return true;
    return false;
}

// `n` candidates of radius 4-12 px scattered within `spread` px of (cx, cy), seeded.
std::vector<LabelRequest> crowd(int n, QPointF centre, double spread, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> offset(-spread, spread), radius(4.0, 12.0);
    std::vector<LabelRequest> labels;
    for (int i = 0; i < n; ++i)
        labels.push_back({centre + QPointF(offset(rng), offset(rng)), radius(rng), QSizeF(70, 13)});
    return labels;
}

// A 480-px-wide pane showing a 480x480 frame of plain carpet, for its overlays alone.
struct CarpetPane {
    ViewTransform transform;
    OverlayOptions options;
    ImageView view{"acquired", &transform, &options};

    explicit CarpetPane(int height)
    {
        view.resize(480, height);
        QImage image(480, 480, QImage::Format_RGB888);
        image.fill(QColor(40, 120, 40));
        view.setImage(image);
    }
};

}  // namespace

class LabelPlacementTest : public QObject {
    Q_OBJECT
private slots:
    void crowdedLabelsNeverOverlap_data()
    {
        QTest::addColumn<int>("count");
        QTest::addColumn<double>("spread");
        QTest::addColumn<unsigned>("seed");
        QTest::newRow("8 within 30 px") << 8 << 30.0 << 1u;
        QTest::newRow("20 within 40 px") << 20 << 40.0 << 2u;
        QTest::newRow("40 on one spot") << 40 << 5.0 << 3u;
        QTest::newRow("12 near the edge") << 12 << 60.0 << 4u;
    }

    void crowdedLabelsNeverOverlap()
    {
        QFETCH(int, count);
        QFETCH(double, spread);
        QFETCH(unsigned, seed);
        const QRectF pane(0, 0, 400, 300);
        const QPointF at = QString(QTest::currentDataTag()).contains("edge") ? QPointF(40, 30) : QPointF(200, 150);
        const std::vector<LabelRequest> labels = crowd(count, at, spread, seed);
        // The set is crowded: labels drawn where the pane used to put them (up and right of
        // each circle) would overlap.
        std::vector<QRectF> naive;
        for (const LabelRequest& l : labels)
            naive.emplace_back(l.centre + QPointF(l.radius + 3, -l.radius - 2 - l.size.height()), l.size);
        QVERIFY(anyOverlap(naive));
        const std::vector<LabelSpot> spots = placeLabels(labels, pane);
        QCOMPARE(spots.size(), labels.size());
        std::vector<QRectF> boxes;
        for (const LabelSpot& s : spots) {
            if (!s.placed) continue;
            QVERIFY(pane.contains(s.box));
            boxes.push_back(s.box);
        }
        QVERIFY(!anyOverlap(boxes, kLabelGapPx));  // apart, so that neighbours read as two
        QVERIFY(spots.front().placed);  // the first (the ball's) always gets its place
        QVERIFY2(int(boxes.size()) >= std::min(count, 8), qPrintable(QString::number(boxes.size())));
    }

    void loneLabelBesideItsCircle()
    {
        const LabelRequest l{QPointF(100, 100), 10.0, QSizeF(60, 12)};
        const std::vector<LabelSpot> spots = placeLabels({l}, QRectF(0, 0, 400, 300));
        QVERIFY(spots[0].placed && !spots[0].leader);
        QVERIFY(spots[0].box.left() > 110 && spots[0].box.left() < 116);  // to the right, a small gap
        QVERIFY(spots[0].box.contains(QPointF(spots[0].box.left() + 1, 100)));
    }

    void displacedLabelGetsALeader()
    {
        // Two circles on the same spot: the second label cannot sit beside its circle.
        std::vector<LabelRequest> labels;
        for (int i = 0; i < 12; ++i) labels.push_back({QPointF(200, 150), 6.0, QSizeF(60, 12)});
        const std::vector<LabelSpot> spots = placeLabels(labels, QRectF(0, 0, 400, 300));
        QVERIFY(spots[0].placed && !spots[0].leader);
        bool anyLeader = false;
        for (const LabelSpot& s : spots) anyLeader |= s.placed && s.leader;
        QVERIFY(anyLeader);
    }

    void paneWithCrowdedCandidates()
    {
        CarpetPane pane(360);
        ImageView& view = pane.view;
        auto overlay = std::make_shared<OverlayData>();
        overlay->config.geometry.centerX = 240;
        overlay->config.geometry.centerY = 240;
        std::mt19937 rng(7);
        std::uniform_int_distribution<int> near(220, 260);
        for (int i = 0; i < 15; ++i) {  // a crowd around the robot, as on a line crossing
            BallCandidate k;
            k.area = i % 3;
            k.x = near(rng);
            k.y = near(rng);
            k.radiusPx = 6;
            k.scores = {98, 100, 96, 0, 0};
            k.scores.squareMeasured = k.scores.shapeMeasured = true;
            k.rejected = i == 0 ? RejectReason::None : RejectReason::Circularity;
            overlay->candidates.push_back(k);
        }
        view.setOverlay(overlay);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        view.grab();  // paints: the labels are placed
        std::vector<QRectF> boxes;
        for (const ImageView::PlacedLabel& l : view.placedLabels()) boxes.push_back(l.box);
        QVERIFY(boxes.size() >= 8);
        QVERIFY(!anyOverlap(boxes, kLabelGapPx));

        // The label explains itself: hovering it names the fields and the thresholds.
        const ImageView::PlacedLabel& first = view.placedLabels().front();
        QCOMPARE(view.candidateAt(first.box.center()), first.candidate);
        QHelpEvent help(QEvent::ToolTip, first.box.center().toPoint(), view.mapToGlobal(first.box.center().toPoint()));
        QApplication::sendEvent(&view, &help);
        QTRY_VERIFY(QToolTip::isVisible());
        const QString tip = QToolTip::text();
        const QString nonGreen = QString("non-green 98 % (min %1 %)").arg(overlay->config.validation.minNonGreenPct);
        for (const QString& word : {QString("radial area"), nonGreen, QString("non-black"), QString("circularity")})
            QVERIFY2(tip.contains(word), qPrintable(tip));
        QToolTip::hideText();
    }

    // A moved candidate (BallCandidate::move) shows the search's centre: a cross there, dotted to
    // its circle. The same candidate unmoved draws nothing between the two.
    void paneShowsWhereAMovedCandidateCameFrom()
    {
        CarpetPane pane(480);
        ImageView& view = pane.view;
        BallCandidate k;
        k.x = 300;
        k.y = 240;
        k.radiusPx = 8;
        k.searchX = 260;
        k.searchY = 240;
        k.rejected = RejectReason::Circularity;
        auto paint = [&](CandidateMove move) {
            auto overlay = std::make_shared<OverlayData>();
            overlay->config.geometry.centerX = 120;
            overlay->config.geometry.centerY = 120;
            k.move = move;
            overlay->candidates = {k};
            view.setOverlay(overlay);
            return view.grab().toImage();
        };
        const QImage still = paint(CandidateMove::None);
        const QImage moved = paint(CandidateMove::ToCircleFit);
        // Between the search's centre and the circle (image x 260-292 on row 240).
        int changed = 0;
        for (int x = 255; x <= 290; ++x) {
            const QPoint at = view.toWidget(QPointF(x, 240)).toPoint();
            for (int dy = -4; dy <= 4; ++dy) changed += moved.pixel(at + QPoint(0, dy)) != still.pixel(at + QPoint(0, dy));
        }
        QVERIFY2(changed >= 12, qPrintable(QString::number(changed)));
        const QPoint cross = view.toWidget(QPointF(k.searchX, k.searchY)).toPoint();
        QCOMPARE(QColor(still.pixel(cross)), QColor(40, 120, 40));
        QVERIFY(QColor(moved.pixel(cross)) != QColor(40, 120, 40));
    }
};

QTEST_MAIN(LabelPlacementTest)
#include "widgets_label_placement_test.moc"

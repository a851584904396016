#include "widgets/CandidateLabel.h"

#include <QCoreApplication>

namespace omnitune {

namespace {

QString tr(const char* text) { return QCoreApplication::translate("omnitune::CandidateLabel", text); }

QString areaName(const BallCandidate& k) { return k.area >= 0 ? QStringLiteral("A%1").arg(k.area + 1) : QStringLiteral("cv"); }

QString pct(double v) { return QString::number(v, 'f', 0); }

// A test validation never ran (a prefilter refusal's shape, a colour refusal's shape on the robot)
// shows "-", as in the candidate table, not a 0 that reads as a failure.
QString measured(double v, bool wasMeasured) { return wasMeasured ? pct(v) : QStringLiteral("-"); }

}  // namespace

QString candidateLabel(const BallCandidate& k)
{
    const ValidationScores& s = k.scores;
    return QStringLiteral("%1 %2/%3/%4").arg(areaName(k), measured(s.nonGreenPct, s.squareMeasured),
                                             measured(s.nonBlackPct, s.squareMeasured),
                                             measured(s.circularityPct, s.shapeMeasured));
}

QString candidateExplanation(const BallCandidate& k, const ValidationOptions& t)
{
    const QString where = k.area >= 0 ? tr("radial area %1 (specific Hough)").arg(k.area + 1) : tr("OpenCV Hough circle");
    const QString verdict = k.rejected == RejectReason::None
                                ? tr("accepted")
                                : tr("rejected: %1").arg(QString::fromUtf8(rejectReasonName(k.rejected).data(),
                                                                            int(rejectReasonName(k.rejected).size())));
    auto line = [](const QString& name, double value, double min, bool wasMeasured) {
        if (!wasMeasured) return tr("%1 not measured").arg(name);
        const QString text = QStringLiteral("%1 %2 % (min %3 %)").arg(name, pct(value), QString::number(min));
        return value < min ? QStringLiteral("<b>%1</b>").arg(text) : text;  // the failed test stands out
    };
    return QStringLiteral("<p><b>%1</b> &mdash; %2, radius %3 px, %4</p><p>%5<br/>%6<br/>%7</p>")
        .arg(candidateLabel(k).toHtmlEscaped(), where, QString::number(k.radiusPx, 'f', 1), verdict,
             line(tr("non-green"), k.scores.nonGreenPct, t.minNonGreenPct, k.scores.squareMeasured),
             line(tr("non-black"), k.scores.nonBlackPct, t.minNonBlackPct, k.scores.squareMeasured),
             line(tr("circularity"), k.scores.circularityPct, requiredCircularityPct(k, t), k.scores.shapeMeasured));
}

QString candidateLabelLegend()
{
    return tr("<b>A3 98/100/96</b>: a candidate in radial area 3 (<b>cv</b>: an OpenCV Hough circle), then its "
              "validation scores in %: <b>non-green</b> / <b>non-black</b> / <b>circularity</b>. Each must reach "
              "its threshold (Validation group of the thresholds). Hover a candidate for its verdict.");
}

}  // namespace omnitune

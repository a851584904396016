#include "widgets/CalibrationPlot.h"

#include <QChart>
#include <QChartView>
#include <QLineSeries>
#include <QValueAxis>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

using namespace QtCharts;

namespace omnitune {

namespace {

constexpr int kMinIterations = 10;  // the x axis shows at least this many, so a short run is not stretched

QLineSeries* line(const QString& name, QColor colour, Qt::PenStyle style = Qt::SolidLine)
{
    auto* s = new QLineSeries;
    s->setName(name);
    s->setPen(QPen(colour, style == Qt::SolidLine ? 2 : 1, style));
    s->setPointsVisible(style == Qt::SolidLine);
    return s;
}

}  // namespace

CalibrationPlot::CalibrationPlot(QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    msv_ = makeChart(tr("Mean sample value"), tr("MSV"), QColor(30, 90, 200));
    wb_ = makeChart(tr("White region chroma - target"), tr("V - target"), QColor(200, 40, 40));
    u_ = line(tr("U - target"), QColor(40, 60, 220));
    wb_.chart->addSeries(u_);
    u_->attachAxis(wb_.x);
    u_->attachAxis(wb_.y);
    wb_.chart->legend()->setVisible(true);
    wb_.chart->legend()->setAlignment(Qt::AlignRight);
    black_ = makeChart(tr("Black region level"), tr("black"), QColor(60, 60, 60));
    for (Chart* c : {&msv_, &wb_, &black_}) {
        auto* view = new QChartView(c->chart, this);
        view->setRenderHint(QPainter::Antialiasing);
        view->setMinimumHeight(110);
        layout->addWidget(view);
    }
    setTargets(CameraAutoOptions{});
}

CalibrationPlot::Chart CalibrationPlot::makeChart(const QString& title, const QString& seriesName, QColor colour)
{
    Chart c;
    c.chart = new QChart;
    c.chart->setTitle(title);
    c.chart->legend()->hide();
    c.chart->setMargins(QMargins(2, 2, 2, 2));
    c.chart->setBackgroundRoundness(0);
    c.series = line(seriesName, colour);
    c.target = line(tr("target"), QColor(40, 150, 60), Qt::DashLine);
    c.chart->addSeries(c.target);
    c.chart->addSeries(c.series);
    c.x = new QValueAxis;
    c.x->setLabelFormat(QStringLiteral("%d"));
    c.x->setRange(0, kMinIterations);
    c.y = new QValueAxis;
    c.y->setTickCount(3);
    c.y->setLabelFormat(QStringLiteral("%.3g"));
    QFont small = c.chart->font();
    small.setPointSizeF(small.pointSizeF() * 0.8);
    for (QValueAxis* a : {c.x, c.y}) a->setLabelsFont(small);
    QFont heading = small;
    heading.setBold(true);
    c.chart->setTitleFont(heading);
    c.chart->addAxis(c.x, Qt::AlignBottom);
    c.chart->addAxis(c.y, Qt::AlignLeft);
    for (QLineSeries* s : {c.series, c.target}) {
        s->attachAxis(c.x);
        s->attachAxis(c.y);
    }
    return c;
}

void CalibrationPlot::setTargets(const CameraAutoOptions& o)
{
    chromaTarget_ = o.chromaTarget;
    regions_ = o.histogramRegions;
    setTarget(msv_, o.msvTarget);
    setTarget(wb_, 0.0);  // the chart shows chroma minus its target
    setTarget(black_, o.blackTarget);
    clear();
}

void CalibrationPlot::setTarget(Chart& c, double value)
{
    c.targetValue = value;
    extendTargets(int(c.x->max()));
}

void CalibrationPlot::clear()
{
    for (Chart* c : {&msv_, &wb_, &black_}) {
        c->series->clear();
        c->x->setRange(0, kMinIterations);
    }
    u_->clear();
    msv_.y->setRange(1, regions_);
    wb_.y->setRange(-10, 10);
    black_.y->setRange(0, std::max(40.0, 2 * black_.targetValue));
    extendTargets(kMinIterations);
}

void CalibrationPlot::addIteration(int iteration, double msv, double u, double v, double black)
{
    msv_.series->append(iteration, msv);
    u_->append(iteration, u - chromaTarget_);
    wb_.series->append(iteration, v - chromaTarget_);
    black_.series->append(iteration, black);
    const int last = std::max(kMinIterations, iteration);
    for (Chart* c : {&msv_, &wb_, &black_}) c->x->setRange(0, last);
    extendTargets(last);
    fit(msv_, msv, msv);
    fit(wb_, std::min(u, v) - chromaTarget_, std::max(u, v) - chromaTarget_);
    fit(black_, black, black);
}

void CalibrationPlot::fit(Chart& c, double low, double high)
{
    const double margin = 0.05 * std::max(1.0, high - low);
    if (low - margin < c.y->min()) c.y->setMin(std::floor(low - margin));
    if (high + margin > c.y->max()) c.y->setMax(std::ceil(high + margin));
}

void CalibrationPlot::extendTargets(int lastIteration)
{
    for (Chart* c : {&msv_, &wb_, &black_})
        c->target->replace(QVector<QPointF>{{0, c->targetValue}, {double(lastIteration), c->targetValue}});
}

}  // namespace omnitune

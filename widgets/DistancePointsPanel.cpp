#include "widgets/DistancePointsPanel.h"

#include "calib/fit/CalibrationPointsCsv.h"
#include "widgets/ConfigDocument.h"
#include "widgets/DistanceFitPlot.h"
#include "widgets/DistancePointsModel.h"
#include "widgets/ImageView.h"
#include "widgets/PaneInput.h"
#include "widgets/PaneSketch.h"
#include "widgets/PipelineView.h"

#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QInputDialog>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QSpinBox>
#include <QTableView>
#include <QVBoxLayout>

namespace omnitune {

namespace {

constexpr const char* kHeightKey = "distance_map.viewpoint_height";

}  // namespace

DistancePointsPanel::DistancePointsPanel(ConfigDocument* doc, PipelineView* view, QWidget* parent)
    : QWidget(parent), doc_(doc), view_(view), model_(new DistancePointsModel(this)), plot_(new DistanceFitPlot(this)),
      table_(new QTableView(this)), addButton_(new QPushButton(tr("&Add points on the panes"), this)),
      degree_(new QSpinBox(this)), height_(new QDoubleSpinBox(this)), status_(new QLabel(this))
{
    setObjectName(QStringLiteral("distancePoints"));
    auto* layout = new QVBoxLayout(this);
    auto* help = new QLabel(tr("Click an image point whose ground distance from the robot centre you measured (a mark "
                               "on the floor, a line crossing with the robot at a known pose) and type the distance; "
                               "or load a POINTS.csv. Then fit."),
                            this);
    help->setWordWrap(true);
    layout->addWidget(help);
    auto* buttons = new QHBoxLayout;
    addButton_->setCheckable(true);
    addButton_->setObjectName(QStringLiteral("addDistancePoints"));
    connect(addButton_, &QPushButton::toggled, this, &DistancePointsPanel::setAdding);
    buttons->addWidget(addButton_);
    auto* load = new QPushButton(tr("&Load CSV..."), this);
    connect(load, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load calibration points"), QString(),
                                                          tr("Points (*.csv *.txt);;All files (*)"));
        if (!path.isEmpty()) loadPoints(path);
    });
    buttons->addWidget(load);
    auto* remove = new QPushButton(tr("&Remove"), this);
    connect(remove, &QPushButton::clicked, this, [this] {
        model_->removePoint(table_->currentIndex().row());
        showPoints();
    });
    buttons->addWidget(remove);
    layout->addLayout(buttons);
    table_->setModel(model_);
    table_->setSelectionBehavior(QAbstractItemView::SelectRows);
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->verticalHeader()->setDefaultSectionSize(table_->fontMetrics().height() + 4);
    layout->addWidget(table_, 1);

    auto* form = new QFormLayout;
    degree_->setRange(1, 6);
    degree_->setValue(DistanceMapFitOptions{}.degree);
    degree_->setToolTip(tr("Polynomial degree; it needs degree + 2 points. A fit that bends back is refused"));
    form->addRow(tr("Fit degree"), degree_);
    height_->setObjectName(QStringLiteral("viewpointHeight"));
    height_->setDecimals(3);
    height_->setSuffix(tr(" m"));
    if (const ConfigKey* k = findConfigKey(kHeightKey)) height_->setRange(k->min, k->max);
    height_->setSingleStep(0.01);
    height_->setToolTip(tr("Height of the mirror's viewpoint above the floor. The ball's centre is a ball radius above the "
                           "floor, so the ray through it meets the floor behind the ball: its distance is scaled by "
                           "(H - r) / H. Measure it once per robot (about 0.75 m on the thesis robot)"));
    height_->setValue(doc_->config().distanceMap.viewpointHeight);
    connect(height_, qOverload<double>(&QDoubleSpinBox::valueChanged), this, [this](double v) {
        if (const auto why = doc_->setValue(kHeightKey, v)) report(*why, true);
    });
    connect(doc_, &ConfigDocument::changed, this, [this] {
        const double h = doc_->config().distanceMap.viewpointHeight;
        if (height_->value() != h) {
            const QSignalBlocker block(height_);
            height_->setValue(h);
        }
    });
    form->addRow(tr("Camera height (ball-height correction)"), height_);
    layout->addLayout(form);
    auto* fitButton = new QPushButton(tr("&Fit distance map"), this);
    fitButton->setObjectName(QStringLiteral("fitDistanceMap"));
    connect(fitButton, &QPushButton::clicked, this, &DistancePointsPanel::fit);
    layout->addWidget(fitButton);
    layout->addWidget(plot_, 1);
    status_->setWordWrap(true);
    status_->setMinimumHeight(status_->fontMetrics().lineSpacing() * 3 + 4);  // a fit's summary, unclipped
    status_->setObjectName(QStringLiteral("distanceStatus"));
    layout->addWidget(status_);

    ask_ = [this](QPointF p) -> std::optional<double> {
        bool ok = false;
        const double d = QInputDialog::getDouble(this, tr("Ground distance"),
                                                 tr("Ground distance from the robot centre to the point at (%1, %2) px, in metres:")
                                                     .arg(p.x(), 0, 'f', 1).arg(p.y(), 0, 'f', 1),
                                                 1.0, 0.0, 100.0, 3, &ok);
        return ok ? std::optional<double>(d) : std::nullopt;
    };
    connectPaneInput(view_, this, &DistancePointsPanel::onPressed, &DistancePointsPanel::ignore, &DistancePointsPanel::ignore);
    for (int i = 0; i < PipelineView::kPaneCount; ++i)
        sketches_.push_back(new PaneSketch(view_->pane(i), [this](QPainter& p, const ImageView& v) { paintPoints(p, v); }));
    connect(model_, &QAbstractItemModel::rowsInserted, this, [this] { for (QWidget* w : sketches_) w->update(); });
    connect(model_, &QAbstractItemModel::rowsRemoved, this, [this] { for (QWidget* w : sketches_) w->update(); });
    connect(model_, &QAbstractItemModel::modelReset, this, [this] { for (QWidget* w : sketches_) w->update(); });
    showPoints();
}

cv::Point2d DistancePointsPanel::centre() const
{
    return {doc_->config().geometry.centerX, doc_->config().geometry.centerY};
}

QString DistancePointsPanel::status() const { return status_->text(); }

void DistancePointsPanel::report(const QString& text, bool problem)
{
    status_->setText(text);
    status_->setStyleSheet(problem ? QStringLiteral("color: #c03020") : QString());
    emit message(text);
}

void DistancePointsPanel::setAdding(bool on)
{
    if (on == adding_) return;
    adding_ = on;
    emit addingChanged(on);  // the other editors give the left button up first
    holdPanes(view_, this, on);
    if (addButton_->isChecked() != on) addButton_->setChecked(on);
    for (QWidget* w : sketches_) w->setVisible(on);
    if (on) report(tr("Click a point on any pane whose ground distance you know"), false);
}

void DistancePointsPanel::onPressed(QPointF p)
{
    const std::optional<double> d = ask_(p);
    if (!d) return;
    model_->addImagePoint(p.x(), p.y(), *d);
    showPoints();
    report(tr("%1 point(s); Fit when they span the radii you need").arg(model_->rowCount()), false);
}

bool DistancePointsPanel::loadPoints(const QString& path)
{
    const CalibrationPointsParse parsed = loadCalibrationPoints(path.toStdString());
    if (!parsed.ok()) {
        report(QString::fromStdString(parsed.error->toString()), true);
        return false;
    }
    model_->setPoints(parsed.points);
    showPoints();
    QString text = tr("%1 point(s) from %2").arg(parsed.points.size()).arg(QFileInfo(path).fileName());
    if (!parsed.warnings.empty())
        text += tr("; %1 row(s) skipped, the first: %2").arg(parsed.warnings.size()).arg(QString::fromStdString(parsed.warnings.front().toString()));
    report(text, !parsed.warnings.empty());
    return true;
}

void DistancePointsPanel::showPoints() { plot_->setData(model_->distancePoints(centre()), std::nullopt); }

bool DistancePointsPanel::fit()
{
    const std::vector<DistancePoint> points = model_->distancePoints(centre());
    DistanceMapFitOptions options;
    options.degree = degree_->value();
    const DistanceMapFitResult result = fitDistanceMap(points, options);
    if (!result.ok()) {
        model_->setResiduals({});
        plot_->setData(points, std::nullopt);
        report(tr("Not fitted, nothing changed: %1").arg(QString::fromStdString(result.error->toString())), true);
        return false;
    }
    Config next = doc_->config();
    applyDistanceMapFit(result.fit, next.distanceMap);
    if (const auto why = doc_->replaceConfig(next, tr("Fit distance map"))) {
        report(tr("The fitted map was refused: %1").arg(*why), true);
        return false;
    }
    model_->setResiduals(result.fit.residualsCm);
    plot_->setData(points, result.fit);
    report(tr("Distance map fitted to %1 points: RMS %2 cm, largest %3 cm; %4 radii from %5 to %6 px written (Ctrl+Z undoes)")
               .arg(points.size()).arg(result.fit.rmsCm, 0, 'f', 1).arg(result.fit.maxAbsCm, 0, 'f', 1)
               .arg(result.fit.tableRadiiPx.size()).arg(result.fit.minRadiusPx, 0, 'f', 0).arg(result.fit.maxRadiusPx, 0, 'f', 0) +
               (result.fit.note.empty() ? QString() : QStringLiteral("; ") + QString::fromStdString(result.fit.note)),
           false);
    return true;
}

// The clicked points, each with its distance, over one pane.
void DistancePointsPanel::paintPoints(QPainter& p, const ImageView& pane) const
{
    for (const CalibrationPoint& q : model_->points()) {
        if (!q.fromImagePoint) continue;
        const QPointF w = pane.toWidget(QPointF(q.xPx, q.yPx));
        p.setPen(QPen(Qt::black, 3));
        p.drawLine(w - QPointF(5, 5), w + QPointF(5, 5));
        p.drawLine(w - QPointF(5, -5), w + QPointF(5, -5));
        p.setPen(QPen(QColor(255, 200, 0), 1));
        p.drawLine(w - QPointF(5, 5), w + QPointF(5, 5));
        p.drawLine(w - QPointF(5, -5), w + QPointF(5, -5));
        p.drawText(w + QPointF(7, -4), tr("%1 m").arg(q.distanceM, 0, 'f', 2));
    }
}

}  // namespace omnitune

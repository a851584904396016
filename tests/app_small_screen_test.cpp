// The window on a 1366x768 laptop (issue 13, venue ergonomics), offscreen: it opens fully on the
// screen's available area (every dock and the status bar inside), the Validation thresholds are
// a few letters away in the search box, "apply to whole session" shows its result in a dock
// beside the panes instead of a window over them, the overlay legend names every field of a
// candidate's label, and the window carries its icons.
#include "app/MainWindow.h"
#include "widgets/ColourEditor.h"
#include "widgets/ImageView.h"
#include "widgets/OverlayLegend.h"
#include "widgets/PipelineView.h"
#include "widgets/ScreenFit.h"
#include "widgets/SessionSweepPanel.h"
#include "widgets/ThresholdPanel.h"
#include "WindowTestSupport.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QMenuBar>
#include <QScreen>
#include <QScrollArea>
#include <QStatusBar>
#include <QToolTip>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

namespace {

// A 1366x768 laptop with a 32 px panel at the top.
const QRect kLaptop(0, 32, 1366, 768 - 32);

// OMNITUNE_SHOTS=DIR saves what a test shows, for docs/images (run under xvfb at 1366x768).
// With `screen`, the screen's pixels where the window is (a tooltip is a window of its own; xcb).
void shot(QWidget* w, const QString& name, bool screen = false)
{
    const QByteArray dir = qgetenv("OMNITUNE_SHOTS");
    if (dir.isEmpty()) return;
    const QRect r = w->frameGeometry();
    QPixmap pixels;
    if (screen && QGuiApplication::platformName() != "offscreen")
        pixels = w->screen()->grabWindow(0, r.x(), r.y(), r.width(), r.height());
    if (pixels.isNull()) pixels = w->grab();
    pixels.save(QString::fromLocal8Bit(dir) + "/" + name);
}

QRect globalRect(const QWidget* w) { return QRect(w->mapToGlobal(QPoint(0, 0)), w->size()); }

QString describe(const QRect& r)
{
    return QString("at %1,%2 %3x%4").arg(r.x()).arg(r.y()).arg(r.width()).arg(r.height());
}

// The window with its frame, every dock on screen (a tab behind another is not) and the status
// bar, with what is wrong when one leaves `area`.
QString outside(const QMainWindow& window, const QRect& area)
{
    QStringList faults;
    if (!area.contains(window.frameGeometry())) faults << "window " + describe(window.frameGeometry());
    QList<QWidget*> parts{window.statusBar(), window.menuBar()};
    for (QDockWidget* dock : window.findChildren<QDockWidget*>())
        if (dock->isVisible() && !dock->visibleRegion().isEmpty()) parts << dock;
    for (QWidget* w : parts) {
        const QRect r = globalRect(w);
        if (!area.contains(r)) faults << w->metaObject()->className() + QString(" ") + w->objectName() + " " + describe(r);
    }
    return faults.join("; ");
}

}  // namespace

class SmallScreenTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    std::unique_ptr<MainWindow> window_;
    QSize frame_;  // the platform's window decoration

private slots:
    void initTestCase()
    {
        startWindowTests();
    }

    void init()
    {
        const QString session = tmp_.filePath(QStringLiteral("%1/demo").arg(QDateTime::currentMSecsSinceEpoch()));
        QVERIFY(copyDemo(session));
        window_ = std::make_unique<MainWindow>();
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
        // What fitToScreen() does on such a screen (the offscreen platform's own is 800x600).
        frame_ = window_->frameGeometry().size() - window_->geometry().size();
        window_->setGeometry(fitWindowGeometry(QSize(1366, 768), frame_, kLaptop));
        QVERIFY(window_->openSource(session));
        QVERIFY(waitForFrame(*window_, 0));
    }

    void cleanup()
    {
        if (window_) window_->document()->undoStack()->setClean();
        window_.reset();
    }

    void fitsTheAvailableArea()
    {
        shot(window_.get(), "workbench-1366x768.png");
        // Smaller than the preferred size on a laptop, and centred; on a big screen the preferred size.
        const QRect fitted = fitWindowGeometry(QSize(1366, 768), QSize(8, 38), kLaptop);
        QVERIFY(kLaptop.contains(fitted.adjusted(-4, -34, 4, 4)));  // with its frame
        QCOMPARE(fitted.width(), 1366 - 8);
        QCOMPARE(fitted.height(), 768 - 32 - 38);
        const QRect big = fitWindowGeometry(QSize(1366, 768), QSize(8, 38), QRect(0, 0, 1920, 1080));
        QCOMPARE(big.size(), QSize(1366, 768));
        QVERIFY(qAbs(big.center().x() - 960) <= 1);

        // The window can be that small: nothing forces it past the screen's bottom or right edge.
        QVERIFY2(outside(*window_, kLaptop).isEmpty(), qPrintable(outside(*window_, kLaptop)));
        QCOMPARE(window_->geometry(), fitWindowGeometry(QSize(1366, 768), frame_, kLaptop));
        QVERIFY(window_->statusBar()->isVisible());
        for (int i = 0; i < PipelineView::kPaneCount; ++i) QVERIFY(window_->pipelineView()->pane(i)->height() >= 120);
    }

    void constructorFitsItsScreen()
    {
        // The window sizes itself for the screen it opens on (offscreen: 800x600, smaller than it wants).
        MainWindow fresh;
        const QRect available = fresh.screen()->availableGeometry();
        QCOMPARE(fresh.size(), fitWindowGeometry(QSize(1366, 768), QSize(8, 38), available).size());
        QVERIFY(available.contains(fresh.geometry()));
    }

    void searchReachesTheValidationGroup()
    {
        ThresholdPanel* panel = window_->thresholdPanel();
        QLineEdit* search = panel->searchBox();
        QVERIFY(search->isVisible());
        QWidget* circularity = panel->editorFor("validation.min_circularity_pct");
        auto* scroll = panel->findChild<QScrollArea*>();
        const auto inView = [scroll](QWidget* w) {
            return w->isVisible() && scroll->viewport()->rect().contains(QRect(w->mapTo(scroll->viewport(), QPoint(0, 0)), w->size()));
        };
        QVERIFY(!inView(circularity));  // below the fold on this screen: the reason for the search box
        search->setFocus();
        QTest::keyClicks(search, "valid");
        QTRY_VERIFY(inView(circularity));
        QVERIFY(!panel->editorFor("edges.canny_low")->isVisible());
        shot(window_.get(), "thresholds-search.png");
        QTest::keyClick(search, Qt::Key_Escape);
        QTRY_VERIFY(panel->editorFor("edges.canny_low")->isVisible());
    }

    void sweepResultDocksBesideThePanes()
    {
        QVERIFY(!window_->document()->setValue("validation.min_circularity_pct", ConfigValue(100.0)));
        QVERIFY(!window_->document()->setValue("validation.circle_fit", ConfigValue(false)));  // thesis' band
        const QRect panesBefore = globalRect(window_->pipelineView());
        window_->findChild<QAction*>("applyToSession")->trigger();
        auto* panel = window_->findChild<SessionSweepPanel*>();
        QVERIFY(panel);
        QSignalSpy finished(panel, &SessionSweepPanel::sweepFinished);
        QVERIFY(finished.wait(60000));
        QVERIFY(!panel->isWindow());  // not a window of its own over the panes
        auto* dock = qobject_cast<QDockWidget*>(panel->parentWidget());
        QVERIFY(dock);
        QCOMPARE(dock->objectName(), QString("wholeSession"));
        QVERIFY(dock->isVisible() && !dock->isFloating());
        QVERIFY(panel->isVisible());
        QVERIFY(window_->tabifiedDockWidgets(dock).contains(window_->findChild<QDockWidget*>("thresholds")));
        QVERIFY(panel->summaryText().contains("vanished"));
        shot(window_.get(), "whole-session.png");
        // The panes stay where they were (the tab may be a little wider than the thresholds');
        // nothing left the screen.
        const QRect panes = globalRect(window_->pipelineView());
        QCOMPARE(panes.topLeft(), panesBefore.topLeft());
        QCOMPARE(panes.height(), panesBefore.height());
        QVERIFY2(panes.width() >= panesBefore.width() * 95 / 100, qPrintable(describe(panes)));
        QVERIFY2(outside(*window_, kLaptop).isEmpty(), qPrintable(outside(*window_, kLaptop)));
    }

    void legendExplainsTheLabels()
    {
        auto* dock = window_->findChild<QDockWidget*>("legend");
        QVERIFY(dock);
        auto* legend = qobject_cast<OverlayLegend*>(dock->widget());
        QVERIFY(legend);
        const QString text = legend->text();
        for (const char* field : {"A3 98/100/96", "radial area", "non-green", "non-black", "circularity", "OpenCV",
                                  "Ground truth", "rejected", "Accepted ball", "moved by a second look"})
            QVERIFY2(text.contains(field, Qt::CaseInsensitive), qPrintable(QString(field) + " not in:\n" + text));
        // Reachable from the View menu, and a tab beside the thresholds.
        bool inViewMenu = false;
        for (QAction* menu : window_->menuBar()->actions())
            if (menu->menu() && menu->text() == "&View") inViewMenu = menu->menu()->actions().contains(dock->toggleViewAction());
        QVERIFY(inViewMenu);
        QVERIFY(dock->toggleViewAction()->isChecked());
        QVERIFY(window_->tabifiedDockWidgets(dock).contains(window_->findChild<QDockWidget*>("thresholds")));
        dock->raise();
        QTRY_VERIFY(legend->isVisible());
        shot(window_.get(), "legend.png");
        QVERIFY2(outside(*window_, kLaptop).isEmpty(), qPrintable(outside(*window_, kLaptop)));
    }

    void candidateTooltipExplainsTheLabel()
    {
        ImageView* pane = window_->pipelineView()->pane(0);
        pane->repaint();
        QVERIFY(!pane->placedLabels().empty());
        const ImageView::PlacedLabel* label = nullptr;
        for (const ImageView::PlacedLabel& l : pane->placedLabels())
            if (l.candidate >= 0) label = &l;
        QVERIFY(label);
        const QPoint at = label->box.center().toPoint();
        QHelpEvent help(QEvent::ToolTip, at, pane->mapToGlobal(at));
        QApplication::sendEvent(pane, &help);
        QTRY_VERIFY(QToolTip::isVisible());
        QVERIFY2(QToolTip::text().contains("circularity") && QToolTip::text().contains("min"), qPrintable(QToolTip::text()));
        for (QWidget* w : QApplication::topLevelWidgets())
            if (w->inherits("QTipLabel")) QVERIFY(QTest::qWaitForWindowExposed(w));
        shot(window_.get(), "candidate-tooltip.png", true);
        QToolTip::hideText();
    }

    // Narrower screens than the laptop's (a 1280x800 projector, a 1400x850 netbook): the window
    // and its docks stay on the screen, the thresholds' search box clear of its dock's edges and
    // no wider than the groups under it (it ran under the window's edge), and the Colours tab's
    // shares lines whole.
    void narrowerScreensKeepTheDocksWhole_data()
    {
        QTest::addColumn<QRect>("screen");
        QTest::newRow("1280x800") << QRect(0, 0, 1280, 800);
        QTest::newRow("1400x850") << QRect(0, 0, 1400, 850);
    }

    void narrowerScreensKeepTheDocksWhole()
    {
        QFETCH(QRect, screen);
        window_->setGeometry(fitWindowGeometry(QSize(1366, 768), frame_, screen));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        QVERIFY(waitForFrame(*window_, 0));
        const QString tag = QTest::currentDataTag();
        shot(window_.get(), "workbench-" + tag + ".png");
        QVERIFY2(outside(*window_, screen).isEmpty(), qPrintable(outside(*window_, screen)));

        auto* thresholds = window_->findChild<QDockWidget*>("thresholds");
        QLineEdit* search = window_->thresholdPanel()->searchBox();
        auto* scroll = window_->thresholdPanel()->findChild<QScrollArea*>();
        const QRect dock = globalRect(thresholds), box = globalRect(search), content = globalRect(scroll->viewport());
        // Clear of the dock's edges (the window's on the right) and not over the scroll bar.
        QVERIFY2(dock.adjusted(2, 0, -2, 0).contains(box) && box.right() <= content.right(),
                 qPrintable(describe(box) + " in " + describe(dock) + ", groups in " + describe(content)));

        auto* colours = window_->findChild<QDockWidget*>("colours");
        colours->raise();
        QLabel* shares = window_->colourEditor()->sharesLabel();
        QTRY_VERIFY(shares->text().contains("two or more"));
        QCoreApplication::sendPostedEvents(nullptr, QEvent::LayoutRequest);
        auto* colourScroll = window_->colourEditor()->findChild<QScrollArea*>("colourScroll");
        QVERIFY(colourScroll);
        const QRect viewport = globalRect(colourScroll->viewport()), label = globalRect(shares);
        QVERIFY2(shares->width() >= shares->sizeHint().width() && shares->height() >= shares->sizeHint().height(),
                 qPrintable(QString("%1x%2 for %3x%4").arg(shares->width()).arg(shares->height())
                                .arg(shares->sizeHint().width()).arg(shares->sizeHint().height())));
        QVERIFY2(label.left() >= viewport.left() && label.right() <= viewport.right(),
                 qPrintable(describe(label) + " in " + describe(viewport)));
        colourScroll->ensureWidgetVisible(shares);
        shot(window_.get(), "colours-" + tag + ".png");
        thresholds->raise();
    }

    void windowHasItsIcons()
    {
        QVERIFY(!window_->windowIcon().isNull());
        QVERIFY(!window_->windowIcon().pixmap(48, 48).isNull());
        QVERIFY(!window_->findChild<QAction*>("applyToSession")->icon().isNull());
    }
};

QTEST_MAIN(SmallScreenTest)
#include "app_small_screen_test.moc"

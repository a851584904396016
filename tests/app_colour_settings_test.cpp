// The Colours tab's settings that live in the config (issue 10), in the window offscreen on a
// copy of the demo session: validation.ball_hint_class is a combo box of the class names that
// may be the ball (not field classes); renaming the class the hint names renames the hint in the
// same undo step, the config stays valid and undo restores both. The sampling outlier share is
// colors.sample_outlier_percent: the tab's spin box edits it as an undo step and the sampler
// fits boxes with it.
#include "app/MainWindow.h"
#include "core/ConfigSchema.h"
#include "widgets/ColourEditor.h"
#include "widgets/ColourSampler.h"
#include "widgets/ConfigDocument.h"
#include "WindowTestSupport.h"

#include <QComboBox>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QtTest>

using namespace omnitune;
using namespace omnitune::testing;

class ColourSettingsTest : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    std::unique_ptr<MainWindow> window_;

    bool open()
    {
        const QString session = freshDemo(tmp_);
        return !session.isEmpty() && openWindow(window_, session, Shown::AsIs);
    }
    ConfigDocument* doc() const { return window_->document(); }
    QComboBox* hintCombo() const { return window_->findChild<QComboBox*>(QStringLiteral("validation.ball_hint_class")); }

private slots:
    void initTestCase()
    {
        startWindowTests();
    }
    void cleanup() { window_.reset(); }

    void ballHintIsAClassNameAndFollowsARename()
    {
        QVERIFY(open());
        QComboBox* combo = hintCombo();
        QVERIFY(combo);
        QStringList names;
        for (int i = 0; i < combo->count(); ++i) names << combo->itemData(i).toString();
        QVERIFY(names.contains(QStringLiteral("none")));
        QVERIFY(names.contains(QStringLiteral("orange")));
        QVERIFY(names.contains(QStringLiteral("yellow")));
        QVERIFY(!names.contains(QStringLiteral("green")));  // a field class is never the ball

        // Pick orange in the combo: the config's hint.
        combo->setCurrentIndex(combo->findData(QStringLiteral("orange")));
        QCOMPARE(doc()->config().validation.ballHint, std::string("orange"));

        // Rename orange in the Colours tab: the hint follows, in one undo step.
        ColourEditor* editor = window_->colourEditor();
        editor->selectClass(findColourClass(doc()->config().colors.classes, "orange"));
        const int steps = doc()->undoStack()->count();
        QVERIFY(!editor->renameClass(QStringLiteral("ball_orange")));
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        QCOMPARE(doc()->config().validation.ballHint, std::string("ball_orange"));
        QVERIFY(findColourClass(doc()->config().colors.classes, "ball_orange") >= 0);
        QVERIFY(checkConfig(doc()->config()).empty());
        QCOMPARE(combo->currentData().toString(), QStringLiteral("ball_orange"));

        doc()->undoStack()->undo();
        QCOMPARE(doc()->config().validation.ballHint, std::string("orange"));
        QVERIFY(findColourClass(doc()->config().colors.classes, "orange") >= 0);
        QCOMPARE(combo->currentData().toString(), QStringLiteral("orange"));
    }

    void outlierShareIsAConfigKey()
    {
        QVERIFY(open());
        auto* spin = window_->colourEditor()->findChild<QDoubleSpinBox*>(QStringLiteral("outlierPct"));
        QVERIFY(spin);
        QCOMPARE(spin->value(), doc()->config().colors.sampleOutlierPct);
        const int steps = doc()->undoStack()->count();
        spin->setValue(5.0);
        QCOMPARE(doc()->config().colors.sampleOutlierPct, 5.0);
        QCOMPARE(doc()->undoStack()->count(), steps + 1);
        QCOMPARE(window_->colourEditor()->sampler()->fitOptions().outlierPct, 5.0);
        // Set elsewhere (the threshold panel, a loaded config): the spin box follows.
        QVERIFY(!doc()->setValue(QStringLiteral("colors.sample_outlier_percent"), 0.0));
        QCOMPARE(spin->value(), 0.0);
        QCOMPARE(window_->colourEditor()->sampler()->fitOptions().outlierPct, 0.0);
        doc()->undoStack()->undo();
        doc()->undoStack()->undo();
        QCOMPARE(spin->value(), 1.0);
    }
};

QTEST_MAIN(ColourSettingsTest)
#include "app_colour_settings_test.moc"

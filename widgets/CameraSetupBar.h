#pragma once
// The yellow strip above the panes that offers to set up a camera the config does not fit yet
// (issue 11): what is wrong in one sentence and the next steps as buttons. It holds no logic;
// CameraSetup decides what it says and what the buttons do.
#include <QFrame>

class QLabel;
class QPushButton;

namespace omnitune {

class CameraSetupBar : public QFrame {
    Q_OBJECT
public:
    explicit CameraSetupBar(QWidget* parent = nullptr);

    // Shows `text` with the buttons asked for (a button not asked for is hidden).
    void showMessage(const QString& text, bool offerAdapt, bool offerSetUp);
    QString text() const;
    QPushButton* adaptButton() const { return adapt_; }
    QPushButton* setUpButton() const { return setUp_; }

signals:
    void adaptRequested();
    void setUpRequested();

private:
    QLabel* label_;
    QPushButton* adapt_;
    QPushButton* setUp_;
};

}  // namespace omnitune

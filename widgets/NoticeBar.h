#pragma once
// A strip above the panes for warnings the user must be able to read in full (a config with
// missing keys, an interrupted session, bad truth rows): they stay until closed, wrap instead
// of being cut off by the status bar's other fields, and can be selected and copied.
#include <QFrame>
#include <QStringList>

class QAction;
class QHBoxLayout;
class QLabel;

namespace omnitune {

class NoticeBar : public QFrame {
    Q_OBJECT
public:
    explicit NoticeBar(QWidget* parent = nullptr);

    // Adds `lines` under `title` ("Opened with warnings: config.yml") and shows the bar.
    void add(const QString& title, const QStringList& lines);
    // A button for `action` beside the text ("Reconnect"), until the bar is cleared.
    void addButton(QAction* action);
    void clear();
    QString text() const;

private:
    QLabel* label_;
    QHBoxLayout* buttons_;
    QStringList entries_;
};

}  // namespace omnitune

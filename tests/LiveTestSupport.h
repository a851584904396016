#pragma once
// Shared by the live-mode tests of the window: opening the simulated camera through the real
// Camera > Live source action and waiting (event driven) for its first processed frame.
#include "widgets/LiveController.h"

#include "WindowTestSupport.h"

#include <QAction>
#include <QApplication>
#include <QFileDialog>
#include <QTimer>

namespace omnitune::testing {

inline bool openSimulatedCamera(MainWindow& w)
{
    auto* action = w.findChild<QAction*>("cameraSource:simulated");
    if (!action) return false;
    action->trigger();
    if (!w.live()->isOpen()) return false;
    QSignalSpy spy(&w, &MainWindow::runShown);
    for (int i = 0; i < 100; ++i) {
        if (w.lastRun() && w.lastRun()->error.isEmpty()) return true;
        spy.wait(200);
    }
    return false;
}

// Answers the next modal folder dialog (QFileDialog::getExistingDirectory) with `folder`, which
// must exist. Event driven: checks again on every turn of the event loop until it is there.
inline void answerNextFolderDialog(const QString& folder)
{
    QTimer::singleShot(0, [folder] {
        if (auto* dialog = qobject_cast<QFileDialog*>(QApplication::activeModalWidget())) {
            dialog->selectFile(folder);
            static_cast<QDialog*>(dialog)->accept();  // (public there): QFileDialog::accept checks the folder
            return;
        }
        answerNextFolderDialog(folder);
    });
}

}  // namespace omnitune::testing

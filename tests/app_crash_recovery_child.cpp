// Helper of app/crash_recovery, not a test: the workbench window on a session (argv[1]) with
// one threshold edit, argv[2] = argv[3] (an integer key), left running with the edit unsaved
// until the test kills it. The recovery folder comes from OMNITUNE_RECOVERY_DIR.
#include "app/MainWindow.h"

#include <QApplication>
#include <QStandardPaths>

#include <cstdio>

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    if (argc != 4) {
        std::fprintf(stderr, "usage: %s SESSION KEY INTEGER\n", argv[0]);
        return 2;
    }
    QStandardPaths::setTestModeEnabled(true);  // recent files: not the user's settings
    omnitune::MainWindow window;
    window.show();
    if (!window.openSource(QString::fromLocal8Bit(argv[1]))) return 3;
    if (const auto refused = window.document()->setValue(argv[2], std::atoi(argv[3]))) {
        std::fprintf(stderr, "edit refused: %s\n", qPrintable(*refused));
        return 4;
    }
    return app.exec();
}

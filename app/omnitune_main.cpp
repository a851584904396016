// omnitune: the workbench window, on the session given as argument or the bundled demo.
#include "app/MainWindow.h"

#include <QApplication>
#include <QDir>
#include <QFileInfo>

int main(int argc, char** argv)
{
    QApplication app(argc, argv);
    QApplication::setApplicationName("OmniTune");
    QApplication::setOrganizationName("OmniTune");  // settings (recent files) in ~/.config/OmniTune
    omnitune::MainWindow window;
    const QString demo = QDir(QApplication::applicationDirPath()).filePath("../../sessions/demo");
    const QString source = argc > 1 ? QString::fromLocal8Bit(argv[1]) : QFileInfo::exists("sessions/demo") ? "sessions/demo" : demo;
    window.show();
    window.openSource(source);
    return app.exec();
}

// omnitune: the workbench window, on the source given as argument or the bundled demo.
#include "app/MainWindow.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QFileInfo>

#include <cstdio>
#include <cstring>

namespace {

void describe(QCommandLineParser& parser)
{
    parser.setApplicationDescription(QCoreApplication::translate(
        "main", "OmniTune workbench: tune and check the ball detector of an omnidirectional camera."));
    parser.addHelpOption();
    parser.addVersionOption();
    parser.addPositionalArgument(QStringLiteral("source"),
                                 QCoreApplication::translate("main", "Session folder, video, image folder or glob, or a "
                                                                     "config.yml (default: the demo session)."),
                                 QStringLiteral("[source]"));
}

void nameApplication()
{
    QCoreApplication::setApplicationName(QStringLiteral("OmniTune"));
    QCoreApplication::setOrganizationName(QStringLiteral("OmniTune"));  // settings (recent files) in ~/.config/OmniTune
    QCoreApplication::setApplicationVersion(QStringLiteral(OMNITUNE_VERSION));
}

// --help and --version answer before any window exists, so they work without a display.
bool asksForInfo(int argc, char** argv)
{
    for (int i = 1; i < argc; ++i)
        for (const char* o : {"-h", "--help", "-?", "--help-all", "-v", "--version"})
            if (std::strcmp(argv[i], o) == 0) return true;
    return false;
}

}  // namespace

int main(int argc, char** argv)
{
    if (asksForInfo(argc, argv)) {
        QCoreApplication info(argc, argv);
        nameApplication();
        QCommandLineParser parser;
        describe(parser);
        parser.process(info);  // prints and exits 0 (or names a wrong option and exits 1)
    }
    QApplication app(argc, argv);  // takes Qt's own options (-platform, -style, ...) out first
    nameApplication();
    QCommandLineParser parser;
    describe(parser);
    if (!parser.parse(QApplication::arguments())) {
        std::fprintf(stderr, "omnitune: %s (omnitune --help lists the options)\n", qPrintable(parser.errorText()));
        return 2;
    }
    const QStringList args = parser.positionalArguments();
    if (args.size() > 1) {
        std::fprintf(stderr, "omnitune: one source at most, got %d (omnitune --help)\n", int(args.size()));
        return 2;
    }
    QString source = args.isEmpty() ? QString() : args.front();
    if (source.isEmpty()) {
        const QString demo = QDir(QApplication::applicationDirPath()).filePath("../../sessions/demo");
        source = QFileInfo::exists("sessions/demo") ? QStringLiteral("sessions/demo") : demo;
    }
    omnitune::MainWindow window;
    window.show();
    window.openPath(source);
    return app.exec();
}

// `cmake --install` puts the window where a desktop finds it: the binary, its .desktop entry
// (Exec and Icon naming what is installed) and the application icon in the hicolor theme.
// Installs the build tree this test belongs to into a scratch prefix.
#include <QFile>
#include <QImage>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

class InstallTest : public QObject {
    Q_OBJECT
private slots:
    void installsTheDesktopApplication()
    {
        QTemporaryDir prefix;
        QVERIFY(prefix.isValid());
        QProcess install;
        install.start(QStringLiteral(OMNITUNE_CMAKE),
                      {"--install", QStringLiteral(OMNITUNE_BINARY_DIR), "--prefix", prefix.path()});
        QVERIFY(install.waitForFinished(5 * 60 * 1000));
        QVERIFY2(install.exitStatus() == QProcess::NormalExit && install.exitCode() == 0,
                 install.readAllStandardError().constData());

        const QString bin = prefix.filePath("bin/omnitune");
        QVERIFY2(QFileInfo(bin).isExecutable(), qPrintable(bin));
        const QString desktop = prefix.filePath("share/applications/omnitune.desktop");
        QVERIFY2(QFile::exists(desktop), qPrintable(desktop));
        QSettings entry(desktop, QSettings::IniFormat);
        entry.beginGroup("Desktop Entry");
        QCOMPARE(entry.value("Type").toString(), QString("Application"));
        QCOMPARE(entry.value("Name").toString(), QString("OmniTune"));
        QVERIFY(entry.value("Exec").toString().startsWith("omnitune"));
        QCOMPARE(entry.value("Icon").toString(), QString("omnitune"));

        QVERIFY(QFile::exists(prefix.filePath("share/icons/hicolor/scalable/apps/omnitune.svg")));
        for (int size : {48, 256}) {
            const QImage icon(prefix.filePath(QString("share/icons/hicolor/%1x%1/apps/omnitune.png").arg(size)));
            QCOMPARE(icon.size(), QSize(size, size));
        }
    }
};

QTEST_GUILESS_MAIN(InstallTest)
#include "app_install_test.moc"

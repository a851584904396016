// Issue 14, defect 12, in the window: a FIFO named truth.csv in a session is refused with its
// name when the window opens the session's ground truth (before: QFile::open waited for a
// writer and the window hung for good).
#include "widgets/TruthDocument.h"

#include <QtTest>

#include <sys/stat.h>

using namespace omnitune;

class TruthFifoTest : public QObject {
    Q_OBJECT
private slots:
    void fifoTruthIsRefused()
    {
        QTemporaryDir dir;
        const QString truth = dir.filePath("truth.csv");
        QVERIFY(::mkfifo(QFile::encodeName(truth).constData(), 0644) == 0);
        TruthDocument doc;
        const auto err = doc.open(dir.path());
        QVERIFY(err);
        QVERIFY2(err->contains(truth) && err->contains("FIFO"), qPrintable(*err));
        QVERIFY(!doc.isOpen());
    }
};

QTEST_MAIN(TruthFifoTest)
#include "widgets_truth_fifo_test.moc"

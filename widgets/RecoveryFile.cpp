#include "widgets/RecoveryFile.h"

#include "widgets/ConfigDocument.h"
#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"

#include <QCryptographicHash>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QSaveFile>
#include <QStandardPaths>
#include <QUndoStack>

namespace omnitune {

RecoveryFile::RecoveryFile(ConfigDocument* doc, QObject* parent) : QObject(parent), doc_(doc)
{
    debounce_.setSingleShot(true);
    debounce_.setInterval(kDebounceMs);
    maxAge_.setSingleShot(true);
    maxAge_.setInterval(kMaxAgeMs);
    connect(&debounce_, &QTimer::timeout, this, [this] { writeNow(); });
    connect(&maxAge_, &QTimer::timeout, this, [this] { writeNow(); });
    // The stack's index, not ConfigDocument::changed: a command changes the config (and
    // signals) before the stack counts it, when the document does not look dirty yet.
    connect(doc_->undoStack(), &QUndoStack::indexChanged, this, &RecoveryFile::onEdited);
    connect(doc_, &ConfigDocument::dirtyChanged, this, [this](bool dirty) {
        if (!dirty) discard();  // saved, reverted, undone to the saved state or another config loaded
    });
}

RecoveryFile::~RecoveryFile() = default;

bool RecoveryFile::lockedByOther(const QString& file)
{
    if (lock_ && locked_ == file) return false;
    lock_.reset();
    locked_.clear();
    auto lock = std::make_unique<QLockFile>(file + ".lock");
    lock->setStaleLockTime(0);  // stale only when its process is gone, however old
    if (lock->tryLock(0)) {
        lock_ = std::move(lock);
        locked_ = file;
        return false;
    }
    // Any other fault (an unwritable folder) shows when the file itself is written.
    return lock->error() == QLockFile::LockFailedError;
}

QString RecoveryFile::directory()
{
    const QString dir = qEnvironmentVariable("OMNITUNE_RECOVERY_DIR");
    if (!dir.isEmpty()) return dir;
    return QDir(QStandardPaths::writableLocation(QStandardPaths::AppDataLocation)).filePath("recovery");
}

QString RecoveryFile::fileFor(const QString& configPath)
{
    if (configPath.isEmpty()) return QDir(directory()).filePath("untitled.yml");
    const QFileInfo info(configPath);
    const QString canonical = info.canonicalFilePath();
    const QString key = canonical.isEmpty() ? info.absoluteFilePath() : canonical;
    const QString hash = QCryptographicHash::hash(key.toUtf8(), QCryptographicHash::Sha1).toHex().left(12);
    return QDir(directory()).filePath(QStringLiteral("%1-%2.yml").arg(info.completeBaseName(), hash));
}

void RecoveryFile::setIntervals(int debounceMs, int maxAgeMs)
{
    debounce_.setInterval(debounceMs);
    maxAge_.setInterval(maxAgeMs);
}

void RecoveryFile::onEdited()
{
    if (!doc_->isDirty()) return;
    debounce_.start();  // restarts: a slider being dragged is written once it rests...
    if (!maxAge_.isActive()) maxAge_.start();  // ...or after a minute of dragging at the latest
}

std::optional<QString> RecoveryFile::writeNow()
{
    debounce_.stop();
    maxAge_.stop();
    if (!doc_->isDirty()) return std::nullopt;
    const QString file = fileFor(doc_->path());
    if (!written_.isEmpty() && written_ != file) discard();  // the config was saved elsewhere
    QDir().mkpath(directory());
    if (lockedByOther(file))
        return fail(tr("Unsaved edits cannot be kept for crash recovery in %1: another OmniTune window "
                       "keeps its own edits of this config there").arg(file));
    std::string text = serializeConfig(doc_->config());
    // After the "%YAML" and "---" lines: says what the file is to whoever finds it.
    const std::size_t body = text.find('\n', text.find("---"));
    QString what = doc_->path().isEmpty() ? QStringLiteral("a config with no file yet") : doc_->path();
    what.replace('\n', ' ');  // stays one comment line
    text.insert(body == std::string::npos ? 0 : body + 1,
                "# OmniTune crash recovery: unsaved edits of " + what.toStdString() + "\n");
    QSaveFile out(file);  // temporary file + rename: a kill while writing leaves the last good copy
    if (!out.open(QIODevice::WriteOnly) || out.write(text.data(), qint64(text.size())) != qint64(text.size()) ||
        !out.commit())
        return fail(tr("Unsaved edits cannot be kept for crash recovery in %1: %2").arg(file, out.errorString()));
    written_ = file;
    lastFailure_.clear();
    return std::nullopt;
}

QString RecoveryFile::fail(const QString& why)
{
    if (why != lastFailure_) emit writeFailed(why);  // not again every few seconds
    lastFailure_ = why;
    return why;
}

void RecoveryFile::discard()
{
    debounce_.stop();
    maxAge_.stop();
    if (!written_.isEmpty()) QFile::remove(written_);
    written_.clear();
    lock_.reset();  // unlocks and removes the lock file
    locked_.clear();
}

std::optional<RecoveredEdits> RecoveryFile::pending(const QString& configPath, const Config& saved)
{
    RecoveredEdits edits;
    edits.file = fileFor(configPath);
    if (edits.file == written_ || !QFileInfo::exists(edits.file)) return std::nullopt;
    QLockFile probe(edits.file + ".lock");
    probe.setStaleLockTime(0);
    if (!probe.tryLock(0)) return std::nullopt;  // a running window's live edits, not a crash's
    probe.unlock();
    edits.written = QFileInfo(edits.file).lastModified();
    QFile in(edits.file);
    if (!in.open(QIODevice::ReadOnly)) {
        edits.error = tr("cannot read %1: %2").arg(edits.file, in.errorString());
        return edits;
    }
    const ConfigLoad load = parseConfig(in.readAll().toStdString(), edits.file.toStdString());
    if (!load.ok()) {
        edits.error = QString::fromStdString(load.error->toString());
        return edits;
    }
    edits.changes = diffConfigs(saved, load.config);
    if (edits.changes.empty()) {  // nothing the saved file lacks
        in.close();
        QFile::remove(edits.file);
        return std::nullopt;
    }
    return edits;
}

QStringList RecoveryFile::restore(const RecoveredEdits& edits)
{
    // Keys are checked together (e.g. a minimum below its maximum), so a value refused now
    // may fit once another has changed: retry until no more go in.
    std::vector<ConfigChange> left = edits.changes;
    QStringList refused;
    const int before = doc_->undoStack()->count();
    doc_->undoStack()->beginMacro(tr("Restore recovered edits"));
    for (bool progress = true; progress && !left.empty();) {
        progress = false;
        refused.clear();
        for (auto it = left.begin(); it != left.end();) {
            // The colour classes are a list, not a schema key: one whole-config step.
            std::optional<QString> why;
            if (it->key == "colors.classes") {
                Config next = doc_->config();
                next.colors.classes = it->classes;
                if (next.colors.classes != doc_->config().colors.classes) why = doc_->replaceConfig(next, tr("Colour classes"));
            } else {
                why = doc_->setValue(QString::fromStdString(it->key), it->to);
            }
            if (why) {
                refused << QStringLiteral("%1 (%2)").arg(QString::fromStdString(it->toString()), *why);
                ++it;
            } else {
                it = left.erase(it);
                progress = true;
            }
        }
    }
    doc_->undoStack()->endMacro();
    if (left.size() == edits.changes.size() && doc_->undoStack()->count() > before)
        doc_->undoStack()->undo();  // nothing went in: no empty step that would mark the document unsaved
    if (!written_.isEmpty() && written_ != edits.file) discard();
    if (!lockedByOther(edits.file)) written_ = edits.file;  // this run's now: rewritten on the next edit, removed on save
    return refused;
}

void RecoveryFile::drop(const RecoveredEdits& edits)
{
    QFile::remove(edits.file);
}

}  // namespace omnitune

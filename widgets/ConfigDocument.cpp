#include "widgets/ConfigDocument.h"

#include "core/ConfigParser.h"
#include "core/ConfigWriter.h"

#include <QUndoCommand>

namespace omnitune {

namespace {

// One key changed from one value to another; consecutive edits of the same key (a slider
// being dragged) merge into one undo step.
class SetValueCommand : public QUndoCommand {
public:
    SetValueCommand(ConfigDocument* doc, QString key, ConfigValue before, ConfigValue after)
        : doc_(doc), key_(std::move(key)), before_(std::move(before)), after_(std::move(after))
    {
        setText(QStringLiteral("%1 = %2").arg(key_, QString::fromStdString(formatConfigValue(after_))));
    }
    void undo() override { doc_->applyValue(key_, before_); }
    void redo() override { doc_->applyValue(key_, after_); }
    int id() const override { return 1; }
    bool mergeWith(const QUndoCommand* other) override
    {
        const auto* o = static_cast<const SetValueCommand*>(other);
        if (o->key_ != key_) return false;
        after_ = o->after_;
        setText(o->text());
        return true;
    }

private:
    ConfigDocument* doc_;
    QString key_;
    ConfigValue before_;
    ConfigValue after_;
};

// Several keys (and the mask) at once, from a fit or an adaptation: one undo step, checked as
// a whole, because its steps one by one may pass through invalid configs (a centre outside the
// old image size).
class ReplaceConfigCommand : public QUndoCommand {
public:
    ReplaceConfigCommand(ConfigDocument* doc, Config before, Config after, const QString& text)
        : doc_(doc), before_(std::move(before)), after_(std::move(after))
    {
        setText(text);
    }
    void undo() override { doc_->applyConfig(before_); }
    void redo() override { doc_->applyConfig(after_); }

private:
    ConfigDocument* doc_;
    Config before_;
    Config after_;
};

}  // namespace

ConfigDocument::ConfigDocument(QObject* parent) : QObject(parent)
{
    connect(&undo_, &QUndoStack::cleanChanged, this, [this](bool clean) {
        if (!clean) return;  // a truth mark alone leaves the config as saved
        saved_ = config_;
        updateDirty();
    });
}

void ConfigDocument::markSaved()
{
    undo_.setClean();
    saved_ = config_;
    updateDirty();
}

void ConfigDocument::updateDirty()
{
    bool dirty = false;
    for (const ConfigKey& k : configSchema())
        if (!(k.get(config_) == k.get(saved_))) dirty = true;
    // The colour classes are a list, not a schema key (the class editor replaces them).
    if (config_.colors.classes != saved_.colors.classes) dirty = true;
    // A new mask under the same file name is an edit too (Camera set up proposes one).
    // The same buffer (a copy of the saved config) needs no pixel comparison: the common case
    // on every threshold edit.
    const cv::Mat& a = config_.mask;
    const cv::Mat& b = saved_.mask;
    if (!dirty && a.data != b.data &&
        (a.empty() != b.empty() || (!a.empty() && (a.size() != b.size() || cv::countNonZero(a != b) > 0))))
        dirty = true;
    if (dirty == dirty_) return;
    dirty_ = dirty;
    emit dirtyChanged(dirty_);
}

ConfigValue ConfigDocument::value(const QString& key) const
{
    const ConfigKey* k = findConfigKey(key.toStdString());
    Q_ASSERT(k);
    return k->get(config_);
}

std::optional<QString> ConfigDocument::setValue(const QString& key, const ConfigValue& value)
{
    const ConfigKey* k = findConfigKey(key.toStdString());
    if (!k) return QStringLiteral("unknown config key %1").arg(key);
    const ConfigValue before = k->get(config_);
    if (before == value) return std::nullopt;
    Config trial = config_;
    k->set(trial, value);
    const auto problems = checkConfig(trial);
    if (!problems.empty()) return QString::fromStdString(problems.front().toString());
    undo_.push(new SetValueCommand(this, key, before, value));
    return std::nullopt;
}

std::optional<QString> ConfigDocument::replaceConfig(const Config& next, const QString& text)
{
    const auto problems = checkConfig(next);
    if (!problems.empty()) return QString::fromStdString(problems.front().toString());
    undo_.push(new ReplaceConfigCommand(this, config_, next, text));
    return std::nullopt;
}

void ConfigDocument::applyConfig(const Config& config)
{
    config_ = config;
    updateDirty();
    emit changed(QString());
}

void ConfigDocument::applyValue(const QString& key, const ConfigValue& value)
{
    findConfigKey(key.toStdString())->set(config_, value);
    updateDirty();
    emit changed(key);
}

std::optional<QString> ConfigDocument::load(const QString& path, QStringList* warnings)
{
    const ConfigLoad load = loadConfig(path.toStdString());
    if (!load.ok()) return QString::fromStdString(load.error->toString());
    if (warnings)
        for (const auto& w : load.warnings) *warnings << QString::fromStdString(w.toString());
    reset(load.config, path);
    return std::nullopt;
}

std::optional<QString> ConfigDocument::save()
{
    if (path_.isEmpty()) return QStringLiteral("the config has no file yet: use Save As");
    if (const auto err = saveConfig(config_, path_.toStdString()))
        return QString::fromStdString(err->toString());
    markSaved();
    return std::nullopt;
}

std::optional<QString> ConfigDocument::saveAs(const QString& path)
{
    if (const auto err = saveConfig(config_, path.toStdString()))
        return QString::fromStdString(err->toString());
    if (path != path_) {
        path_ = path;
        emit pathChanged(path_);
    }
    markSaved();
    return std::nullopt;
}

std::optional<QString> ConfigDocument::revert()
{
    if (path_.isEmpty()) return QStringLiteral("the config has no file to revert to");
    return load(path_);
}

void ConfigDocument::discardChanges() { reset(saved_, path_); }

void ConfigDocument::reset(const Config& config, const QString& path)
{
    config_ = config;
    saved_ = config;
    undo_.clear();
    if (path != path_) {
        path_ = path;
        emit pathChanged(path_);
    }
    emit changed(QString());
    dirty_ = false;
    emit dirtyChanged(false);
}

}  // namespace omnitune

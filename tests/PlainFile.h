#pragma once
// A plain file in a temporary folder: a path under it ("<file>/sub") is a folder that cannot be
// made, for tests of the message a writer gives when its output folder is unusable.
#include <QFile>
#include <QTemporaryDir>

#include <filesystem>
#include <string>

inline std::string makePlainFile(const QTemporaryDir& dir)
{
    const std::string file = (std::filesystem::path(dir.path().toStdString()) / "plain-file").string();
    QFile f(QString::fromStdString(file));
    if (!f.open(QIODevice::WriteOnly)) return {};
    return file;
}

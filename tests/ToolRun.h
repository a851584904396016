#pragma once
// Running the command-line tools from a test: one finished run (exit, stdout, stderr) through
// QProcess, and the CSV they print. Shared by the tool tests.
#include <QByteArray>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QString>
#include <QStringList>
#include <QVector>

namespace tooltest {

constexpr int kTimeoutMs = 10 * 60 * 1000;  // generous: a hang fails, a slow sanitizer build does not

// One finished tool run.
struct Run {
    QString command;
    bool finished = false;
    QProcess::ExitStatus status = QProcess::CrashExit;
    int exitCode = -1;
    QByteArray out;
    QByteArray err;

    bool exitedWith(int code) const { return finished && status == QProcess::NormalExit && exitCode == code; }
    // Exited by itself with a non-zero code (a crash or a hang is not a clean refusal).
    bool refused() const { return finished && status == QProcess::NormalExit && exitCode != 0; }
    QStringList errLines() const
    {
        QStringList lines = QString::fromUtf8(err).split('\n');
        while (!lines.isEmpty() && lines.last().trimmed().isEmpty()) lines.removeLast();
        return lines;
    }
    // For failure messages: the command, how it ended and what it said.
    QString describe() const
    {
        QString s = "\n  command: " + command + "\n  ";
        if (!finished)
            s += "did not finish";
        else if (status == QProcess::CrashExit)
            s += "crashed";
        else
            s += "exit code " + QString::number(exitCode);
        s += "\n  stderr: " + QString::fromUtf8(err.left(2000));
        if (out.size() < 400) s += "\n  stdout: " + QString::fromUtf8(out);
        return s;
    }
};

// `program` with `args`; `shellPrefix` non-empty runs it as `sh -c 'PREFIX exec "$0" "$@"'`,
// e.g. "trap '' XFSZ; ulimit -f 1;" for a tiny disk.
inline Run runTool(const QString& program, const QStringList& args, const QString& shellPrefix = {})
{
    Run r;
    r.command = QFileInfo(program).fileName() + " " + args.join(' ');
    QProcess p;
    if (shellPrefix.isEmpty()) {
        p.start(program, args);
    } else {
        r.command = shellPrefix + " " + r.command;
        p.start("/bin/sh", QStringList{"-c", shellPrefix + " exec \"$0\" \"$@\"", program} + args);
    }
    if (!p.waitForStarted(kTimeoutMs)) {
        r.err = "could not start: " + p.errorString().toUtf8();
        return r;
    }
    r.finished = p.waitForFinished(kTimeoutMs);
    if (!r.finished) {
        p.kill();
        p.waitForFinished(kTimeoutMs);
    }
    r.status = p.exitStatus();
    r.exitCode = p.exitCode();
    r.out = p.readAllStandardOutput();
    r.err = p.readAllStandardError();
    return r;
}

// CSV with a header; fields may be quoted ("a, b" and "" for a quote), lines end in \n or \r\n.
struct Csv {
    QStringList header;
    QVector<QStringList> rows;

    int column(const QString& name) const { return header.indexOf(name); }
    QString at(int row, const QString& name) const
    {
        const int c = column(name);
        return c >= 0 && c < rows[row].size() ? rows[row][c] : QString();
    }
    double number(int row, const QString& name) const { return at(row, name).toDouble(); }
};

inline QStringList splitCsvLine(const QString& line)
{
    QStringList fields;
    QString field;
    bool quoted = false;
    for (int i = 0; i < line.size(); ++i) {
        const QChar c = line[i];
        if (quoted) {
            if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                field += '"';
                ++i;
            } else if (c == '"') {
                quoted = false;
            } else {
                field += c;
            }
        } else if (c == '"') {
            quoted = true;
        } else if (c == ',') {
            fields << field;
            field.clear();
        } else {
            field += c;
        }
    }
    fields << field;
    return fields;
}

inline Csv parseCsv(const QByteArray& text)
{
    Csv csv;
    const QStringList lines = QString::fromUtf8(text).split('\n');
    for (QString line : lines) {
        if (line.endsWith('\r')) line.chop(1);
        if (line.isEmpty()) continue;
        if (csv.header.isEmpty())
            csv.header = splitCsvLine(line);
        else
            csv.rows << splitCsvLine(line);
    }
    return csv;
}

inline QByteArray readBytes(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

inline bool writeBytes(const QString& path, const QByteArray& bytes)
{
    QFile f(path);
    return f.open(QIODevice::WriteOnly | QIODevice::Truncate) && f.write(bytes) == bytes.size();
}

}  // namespace tooltest

#include "RecentFiles.h"

#include "ActionTexts.h"

#include <QDir>
#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace pf {

namespace {

constexpr int kMaxRecent = 8;
const QString kSettingsKey = QStringLiteral("recentFiles");

QString absolute(const QString& path) {
    return QDir::cleanPath(QFileInfo(path).absoluteFilePath());
}

// Without `path` and without any entry that names the same file (older sessions kept
// the names they were given, relative ones too).
QStringList without(const QStringList& recent, const QString& path) {
    QStringList kept;
    for (const QString& entry : recent)
        if (entry != path && absolute(entry) != absolute(path)) kept.append(entry);
    return kept;
}

} // namespace

RecentFiles::RecentFiles(QMenu* menu, QObject* parent) : QObject(parent), menu_(menu) {
    rebuildMenu();
}

void RecentFiles::add(const QString& path) {
    QSettings settings;
    QStringList recent = without(settings.value(kSettingsKey).toStringList(), path);
    recent.prepend(absolute(path));
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue(kSettingsKey, recent);
    rebuildMenu();
}

void RecentFiles::remove(const QString& path) {
    QSettings settings;
    settings.setValue(kSettingsKey, without(settings.value(kSettingsKey).toStringList(), path));
    rebuildMenu();
}

void RecentFiles::rebuildMenu() {
    menu_->clear();
    const QStringList recent = QSettings().value(kSettingsKey).toStringList();
    for (const QString& path : recent) {
        QAction* a = menu_->addAction(ActionTexts::literal(QFileInfo(path).fileName()));
        a->setToolTip(path);
        connect(a, &QAction::triggered, this, [this, path] { emit openRequested(path); });
    }
    menu_->setEnabled(!recent.isEmpty());
}

} // namespace pf

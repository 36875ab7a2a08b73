#include "RecentFiles.h"

#include "ActionTexts.h"

#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace pf {

namespace {

constexpr int kMaxRecent = 8;
const QString kSettingsKey = QStringLiteral("recentFiles");

} // namespace

RecentFiles::RecentFiles(QMenu* menu, QObject* parent) : QObject(parent), menu_(menu) {
    rebuildMenu();
}

void RecentFiles::add(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(kSettingsKey).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue(kSettingsKey, recent);
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

#pragma once

#include <QObject>

class QMenu;

namespace pf {

// File ▸ Open Recent: the last sheets opened or saved, kept in the settings.
class RecentFiles : public QObject {
    Q_OBJECT

  public:
    RecentFiles(QMenu* menu, QObject* parent);

    // The path is kept absolute: a sheet opened by a name relative to where the editor
    // was started must open from Open Recent wherever the next session starts.
    void add(const QString& path);
    // Takes the entry off (a sheet that could not be opened from it).
    void remove(const QString& path);

  signals:
    void openRequested(const QString& path);

  private:
    void rebuildMenu();

    QMenu* menu_;
};

} // namespace pf

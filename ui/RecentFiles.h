#pragma once

#include <QObject>

class QMenu;

namespace pf {

// File ▸ Open Recent: the last sheets opened or saved, kept in the settings.
class RecentFiles : public QObject {
    Q_OBJECT

  public:
    RecentFiles(QMenu* menu, QObject* parent);

    void add(const QString& path);

  signals:
    void openRequested(const QString& path);

  private:
    void rebuildMenu();

    QMenu* menu_;
};

} // namespace pf

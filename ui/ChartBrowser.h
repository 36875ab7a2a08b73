#pragma once

#include <QObject>
#include <QString>

class QWidget;

namespace pf {

// The newest speed–accuracy chart `paperfold bench` wrote (bench_*.png), shown in a
// dialog: the solver's developers' view, reached from the Solver dock.
class ChartBrowser : public QObject {
    Q_OBJECT

  public:
    // Dialogs open over `parent`.
    explicit ChartBrowser(QWidget* parent);

    // Where the charts are looked for (remembered in the settings).
    QString folder() const { return folder_; }
    void setFolder(const QString& folder) { folder_ = folder; }
    // The chart shown last.
    QString lastChart() const { return lastChart_; }

    // Shows the newest chart; asks for the folder when the current one holds none.
    void showLatest();

  signals:
    void failed(const QString& message);

  private:
    QWidget* parent_;
    QString folder_;
    QString lastChart_;
};

} // namespace pf

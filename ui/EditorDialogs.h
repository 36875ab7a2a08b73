#pragma once

#include <QCoreApplication>
#include <QMessageBox>
#include <QSize>
#include <QString>

class QWidget;

namespace pf {

enum class FileDialog { Open, Save, ExportImage, ExportMesh, SaveRecording };

// The questions the editor asks, as standard dialogs over `parent`. The window calls them
// through functions a test can replace with scripted answers.
class EditorDialogs {
    Q_DECLARE_TR_FUNCTIONS(pf::EditorDialogs)

  public:
    // Empty when cancelled. `current`: the sheet's file, offered by Save.
    static QString chooseFile(QWidget* parent, FileDialog kind, const QString& current);
    static void showError(QWidget* parent, const QString& message);
    static QMessageBox::StandardButton askToSave(QWidget* parent);
    // "width x height": an invalid QSize when cancelled, 0 x 0 when unreadable.
    static QSize chooseImageSize(QWidget* parent);
};

} // namespace pf

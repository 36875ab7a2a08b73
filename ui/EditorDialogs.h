#pragma once

#include <QColor>
#include <QCoreApplication>
#include <QMessageBox>
#include <QSize>
#include <QString>

class QWidget;

namespace pf {

enum class FileDialog { Open, Save, ExportImage, ExportMesh, SaveRecording, PaperImage };

// The questions the editor asks, as standard dialogs over `parent`. The window calls them
// through functions a test can replace with scripted answers.
class EditorDialogs {
    Q_DECLARE_TR_FUNCTIONS(pf::EditorDialogs)

  public:
    // Empty when cancelled. `current`: the sheet's file, offered by Save. Every file
    // dialog opens in the folder of the last file chosen in one (kept between sessions);
    // they all opened in the folder the editor was started from.
    static QString chooseFile(QWidget* parent, FileDialog kind, const QString& current);
    // Where chooseFile's dialog for `kind` opens: `current` for Save when there is one,
    // else the last folder a file was chosen in, else the home folder.
    static QString startingPlace(FileDialog kind, const QString& current);
    // Notes the folder of a file chosen in a dialog, where the next one opens.
    static void rememberChosen(const QString& chosen);
    static void showError(QWidget* parent, const QString& message);
    static QMessageBox::StandardButton askToSave(QWidget* parent);
    // "width x height": an invalid QSize when cancelled, 0 x 0 when unreadable. Offers
    // `offered`.
    static QSize chooseImageSize(QWidget* parent, const QSize& offered);
    // An invalid colour when cancelled.
    static QColor chooseColor(QWidget* parent, const QColor& current);
    // The subdivision level for Export Mesh, -1 when cancelled.
    static int chooseMeshSubdivision(QWidget* parent, int current);
};

} // namespace pf

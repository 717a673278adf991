//! The app's own words outside the modes: the menu, the presentation size and language
//! controls, the notices, the export dialog and its outcomes, each in English and in
//! Brazilian Portuguese.

use degrau_words::{Lang, Localize, Message};

use crate::persist::problem::{Field, FieldProblem, Reason, SaveFailure};

degrau_words::phrases! {
    /// The labels of the menu, the notices, the export dialog and the file dialogs' kinds
    /// of file.
    pub enum App {
        ModeDesign => ("Poles and zeros", "Polos e zeros"),
        ModeIdentify => ("Identify a step test", "Identificar ensaio"),
        File => ("File", "Arquivo"),
        OpenTest => ("Open a step test…", "Abrir um ensaio ao degrau…"),
        Export => ("Export…", "Exportar…"),
        CopyMatlab => ("Copy as MATLAB code", "Copiar como código MATLAB"),
        CopyPython => ("Copy as python-control code", "Copiar como código python-control"),
        CopiedMatlab => (
            "Copied the system as MATLAB code",
            "Sistema copiado como código MATLAB"
        ),
        CopiedPython => (
            "Copied the system as python-control code",
            "Sistema copiado como código python-control"
        ),
        Reset => ("Reset to the built-in example", "Voltar ao exemplo embutido"),
        Edit => ("Edit", "Editar"),
        Undo => ("Undo", "Desfazer"),
        Redo => ("Redo", "Refazer"),
        DeleteSelected => ("Delete selected root", "Apagar a raiz selecionada"),
        DeleteKey => ("Delete", "Delete (tecla)"),
        View => ("View", "Exibir"),
        DarkTheme => ("Dark theme", "Tema escuro"),
        DampingLines => ("Constant ζ and ωn lines", "Linhas de ζ e ωn constantes"),
        SnapRoots => ("Snap roots to the grid", "Encaixar as raízes na grade"),
        FitSPlane => ("Fit the s-plane to the roots", "Enquadrar o plano s nas raízes"),
        PresentationSize => ("Presentation size", "Tamanho de apresentação"),
        Smaller => ("Smaller text and lines", "Texto e linhas menores"),
        Larger => ("Larger text and lines (for a projector)", "Texto e linhas maiores (para projetor)"),
        Language => ("Language", "Idioma"),
        SizeCapped => (
            "Presentation size limited so this window keeps its menu and plots: enlarge the window for more",
            "Tamanho de apresentação limitado para a janela manter o menu e os gráficos: aumente a janela para mais"
        ),
        Dismiss => ("Dismiss", "Dispensar"),
        NoHome => (
            "There is no home directory to keep the session in: it will not be saved.",
            "Não há diretório pessoal onde guardar a sessão: ela não será salva."
        ),
        NotRestored => (
            "Part of the last session could not be restored and was reset to its default:",
            "Parte da última sessão não pôde ser restaurada e voltou ao padrão:"
        ),
        KeptAs => ("The file as it was is kept as", "O arquivo como estava foi guardado como"),
        NotKeptAside => ("It could not be kept aside:", "Não foi possível guardá-lo à parte:"),
        SaveFailed => ("Could not save the session:", "Não foi possível salvar a sessão:"),
        ExportTitle => ("Export", "Exportar"),
        FileLabel => ("File", "Arquivo"),
        Browse => ("Browse…", "Procurar…"),
        SavePlotPng => ("Save step plot as PNG", "Salvar o gráfico da resposta como PNG"),
        SaveWindowPng => ("Save window as PNG", "Salvar a janela como PNG"),
        SaveCsv => ("Save curve as CSV", "Salvar a curva como CSV"),
        Exists => ("already exists. Overwrite it?", "já existe. Substituir?"),
        Overwrite => ("Overwrite", "Substituir"),
        Cancel => ("Cancel", "Cancelar"),
        Taking => ("Taking the screenshot…", "Capturando a tela…"),
        Saved => ("Saved", "Salvo:"),
        SavedCurve => ("Saved the curve to", "Curva salva em"),
        NotSaved => ("Not saved:", "Não salvo:"),
        CouldNotWrite => ("could not write", "não foi possível gravar"),
        CouldNotEncode => ("could not encode the PNG", "não foi possível codificar o PNG"),
        NoCurve => (
            "there is no curve to save: the system is not valid",
            "não há curva para salvar: o sistema não é válido"
        ),
        NoPath => ("type a file name first", "digite primeiro um nome de arquivo"),
        StepTestFiles => ("step tests", "ensaios ao degrau"),
        InputFiles => ("input", "entrada"),
    }
}

/// Which tool's code "Copy as code" writes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CodeKind {
    Matlab,
    PythonControl,
}

impl CodeKind {
    /// The confirmation once copied.
    pub fn copied(self) -> App {
        match self {
            CodeKind::Matlab => App::CopiedMatlab,
            CodeKind::PythonControl => App::CopiedPython,
        }
    }
}

/// A message for the student at the top of the window, until dismissed.
#[derive(Debug, Clone, PartialEq)]
pub enum Notice {
    /// The state file had no home.
    NoHome,
    /// Fields of the state file that were reset and why, where the file was kept aside or
    /// why it could not be (the system's own words).
    NotRestored {
        fields: Vec<FieldProblem>,
        backup: Option<String>,
        backup_error: Option<String>,
    },
    /// The session could not be written, and why.
    SaveFailed(SaveFailure),
}

impl Localize for Notice {
    fn text(&self, lang: Lang) -> String {
        match self {
            Notice::NoHome => App::NoHome.get(lang).to_string(),
            Notice::NotRestored {
                fields,
                backup,
                backup_error,
            } => {
                let fields: Vec<String> = fields.iter().map(|f| f.text(lang)).collect();
                let mut text = format!("{} {}.", App::NotRestored.get(lang), fields.join("; "));
                if let Some(path) = backup {
                    text.push_str(&format!(" {} {path}.", App::KeptAs.get(lang)));
                }
                if let Some(reason) = backup_error {
                    text.push_str(&format!(" {} {reason}.", App::NotKeptAside.get(lang)));
                }
                text
            }
            Notice::SaveFailed(why) => format!("{} {}", App::SaveFailed.get(lang), why.text(lang)),
        }
    }
}

/// Every message of the app's top level, for the catalogue test.
pub fn messages() -> Vec<Message> {
    let mut all = App::messages();
    let notices = [
        Notice::NoHome,
        Notice::NotRestored {
            fields: vec![FieldProblem {
                field: Field::Path("system.amplitude".into()),
                reason: Reason::Unreadable {
                    found: "\"two\"".into(),
                },
            }],
            backup: Some("state.json.bad-1".into()),
            backup_error: Some("No space left on device (os error 28)".into()),
        },
        Notice::SaveFailed(SaveFailure::Stopped),
    ];
    all.extend(
        notices
            .iter()
            .map(|n| Message::of(format!("Notice::{n:?}"), n)),
    );
    all
}

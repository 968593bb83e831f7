//! `ballscrew man`: the manual of the command line, one page for the command and all its
//! subcommands, from the command's own definition (what `--help` says): a roff man page
//! (`clap_mangen`) or the markdown reference (`crate::reference`, `docs/cli-reference.md`).

use crate::error::CliError;
use clap::ValueEnum;
use clap_mangen::Man;

/// Format of the manual.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ManFormat {
    /// A roff man page (section 1), for `man`.
    Roff,
    /// The markdown command-line reference.
    Markdown,
}

/// Flags of `ballscrew man`.
#[derive(Debug, Clone, clap::Args)]
pub struct ManArgs {
    /// Output format
    #[arg(long, value_enum, default_value_t = ManFormat::Roff)]
    pub format: ManFormat,
}

/// The manual of `command` (the whole command line) in the format of `args`.
pub fn run(command: clap::Command, args: &ManArgs) -> Result<String, CliError> {
    match args.format {
        ManFormat::Roff => roff(command),
        ManFormat::Markdown => Ok(crate::reference::markdown(command)),
    }
}

/// One section's renderer of a [`Man`].
type Render = fn(&Man, &mut dyn std::io::Write) -> std::io::Result<()>;

/// The man page: the command's own page (name, synopsis, description, global options, the list
/// of subcommands), a section per subcommand (`BALLSCREW SWEEP`, ...) with its synopsis,
/// description and options as subsections, then the version.
fn roff(command: clap::Command) -> Result<String, CliError> {
    // `ballscrew help SUBCOMMAND` is `--help`, which the page is: not listed as a subcommand.
    let mut command = command.disable_help_subcommand(true);
    command.build();
    let main = Man::new(command.clone());
    let mut page = String::new();
    let head: [Render; 6] = [
        Man::render_title,
        Man::render_name_section,
        Man::render_synopsis_section,
        Man::render_description_section,
        Man::render_options_section,
        Man::render_subcommands_section,
    ];
    for render in head {
        page.push_str(&section(&main, render, page.is_empty())?);
    }
    // The list names the subcommands' sections of this page, not pages of their own.
    let name = command.get_name();
    for sub in command.get_subcommands() {
        let sub = sub.get_name().replace('-', "\\-");
        page = page.replace(&format!("\n{name}\\-{sub}(1)\n"), &format!("\n\\fB{name} {sub}\\fR\n"));
    }
    for sub in command.get_subcommands().filter(|s| !s.is_hide_set()) {
        let title = format!("{} {}", command.get_name(), sub.get_name()).to_uppercase();
        page.push_str(&format!(".SH \"{title}\"\n"));
        let man = Man::new(sub.clone());
        let body: [Render; 3] =
            [Man::render_synopsis_section, Man::render_description_section, Man::render_options_section];
        for render in body {
            // The subcommand's sections become subsections of its own section.
            for line in section(&man, render, false)?.lines() {
                match line.strip_prefix(".SH ") {
                    Some(heading) => page.push_str(&format!(".SS {heading}\n")),
                    None => page.push_str(&format!("{line}\n")),
                }
            }
        }
    }
    page.push_str(&section(&main, Man::render_version_section, false)?);
    Ok(page)
}

/// One section of a page by `render`; `first`: with the preamble every rendering starts with
/// (the definition of the apostrophe string `Aq`), which the page needs once.
fn section(man: &Man, render: Render, first: bool) -> Result<String, CliError> {
    let mut buf = Vec::new();
    render(man, &mut buf).map_err(|e| CliError::Output(format!("the man page: {e}")))?;
    let text = String::from_utf8(buf).map_err(|e| CliError::Output(format!("the man page: {e}")))?;
    if first {
        return Ok(text);
    }
    Ok(text
        .lines()
        .filter(|l| !l.starts_with(".ie \\n(.g .ds Aq") && !l.starts_with(".el .ds Aq"))
        .map(|l| format!("{l}\n"))
        .collect())
}

import { useStudio, type Tool } from "../store";

const TOOLS: { tool: Tool; label: string; hint: string }[] = [
  { tool: "path", label: "✎ Draw path", hint: "Drag on the floor to draw a path for a person to follow" },
  { tool: "part", label: "☝ Edit part", hint: "Hover a body part, click it to edit it with an instruction" },
];

/** The viewport's modes: draw a path on the floor, or pick a body part to edit. */
export function Tools() {
  const tool = useStudio((s) => s.tool);
  const setTool = useStudio((s) => s.setTool);
  return (
    <div className="tools" role="toolbar" aria-label="Directing tools">
      {TOOLS.map((t) => (
        <button
          key={t.tool}
          data-testid={`tool-${t.tool}`}
          aria-pressed={tool === t.tool}
          className={tool === t.tool ? "active" : ""}
          title={t.hint}
          onClick={() => setTool(t.tool)}
        >
          {t.label}
        </button>
      ))}
      {tool !== "view" && <span className="tools__hint small">{TOOLS.find((t) => t.tool === tool)?.hint}</span>}
    </div>
  );
}

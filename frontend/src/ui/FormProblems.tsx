import { create } from "zustand";
import { formProblems, type FormProblem } from "../api/formCheck";
import { useStudio, type StudioState } from "../store";

/** Whether Generate was pressed with the form as it is (an empty prompt is only pointed out
 * then; a prompt over the limit or seconds out of range are said as they are typed). */
export const useFormTried = create<{ tried: boolean }>(() => ({ tried: false }));

/** The form's problems now (api/formCheck.ts, against the API's limits). */
export function currentProblems(s: StudioState = useStudio.getState()): FormProblem[] {
  return formProblems({ prompt: s.prompt, seconds: s.seconds, persons: s.persons }, s.limits);
}

/** The problems to show under the prompt bar: all after a Generate that they stopped, else
 * those worth saying while typing (not the empty prompt of a fresh page). */
export function shownProblems(problems: FormProblem[], tried: boolean, prompt: string): FormProblem[] {
  return tried ? problems : problems.filter((p) => p.field !== "prompt" || prompt.trim() !== "");
}

/** The prompt form's problems, in plain sentences, under the header (never sent to the server). */
export function FormProblems() {
  const prompt = useStudio((s) => s.prompt);
  const seconds = useStudio((s) => s.seconds);
  const persons = useStudio((s) => s.persons);
  const limits = useStudio((s) => s.limits);
  const tried = useFormTried((s) => s.tried);
  const shown = shownProblems(formProblems({ prompt, seconds, persons }, limits), tried, prompt);
  if (!shown.length) return null;
  return (
    <div className="form-problems" role="alert" data-testid="form-problems" id="form-problems">
      {shown.map((p) => (
        <p key={p.field} data-field={p.field}>
          {p.message}
        </p>
      ))}
    </div>
  );
}

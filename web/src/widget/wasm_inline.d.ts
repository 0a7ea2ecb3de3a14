// vite's ?inline suffix: the file's contents as a base64 data: URL string.
declare module '*.wasm?url&inline' {
  const dataUrl: string;
  export default dataUrl;
}

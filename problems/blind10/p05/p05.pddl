;; Six small things on a mat, two of each kind, sorted into three rimmed
;; bins by kind. The goal is written with forall/exists over the types.
(define (problem blind10-p05)
  (:domain blind10-sort)
  (:objects can-1 can-2 - can
            cube-1 cube-2 - cube
            bar-1 bar-2 - bar
            bin-c - can-bin
            bin-q - cube-bin
            bin-r - bar-bin
            mat - mat)
  (:init (lies can-1 mat) (lies can-2 mat) (lies cube-1 mat)
         (lies cube-2 mat) (lies bar-1 mat) (lies bar-2 mat) (hand-empty))
  (:goal (and (forall (?c - can) (exists (?b - can-bin) (lies ?c ?b)))
              (forall (?q - cube) (exists (?b - cube-bin) (lies ?q ?b)))
              (forall (?r - bar) (exists (?b - bar-bin) (lies ?r ?b)))
              (hand-empty))))
